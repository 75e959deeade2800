# Opens the tool's web page in headless Chromium, kept off the network, takes a screenshot and
# checks that it shows the textured model: each of the texture's two colours covers at least
# SHARE of the pixels (a blank page, a black canvas or an untextured model fails):
#   cmake -DCHROMIUM=<chromium> -DPROBE=<image_probe> -DPAGE=<page.html> -DCOLOURS=<R,G,B;R,G,B>
#         -DSHARE=<fraction> -DSCREENSHOT=<png> -P check_viewer.cmake

get_filename_component(directory "${SCREENSHOT}" DIRECTORY)
set(profile "${SCREENSHOT}.profile")
file(REMOVE_RECURSE "${profile}")
file(REMOVE "${SCREENSHOT}")
file(MAKE_DIRECTORY "${profile}")
# WebGL in software: Chromium's ANGLE on SwiftShader, asked for by name (--use-angle=swiftshader),
# which needs no GPU and no --enable-unsafe-swiftshader (the flag for an automatic fallback).
execute_process(COMMAND "${CHROMIUM}" --headless --no-sandbox --disable-quic --no-first-run
                        --disable-background-networking --disable-component-update --disable-sync
                        --user-data-dir=${profile} --use-angle=swiftshader
                        --window-size=800,600 --virtual-time-budget=15000 --screenshot=${SCREENSHOT}
                        "file://${PAGE}"
                TIMEOUT 180 RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(REMOVE_RECURSE "${profile}")
if(NOT EXISTS "${SCREENSHOT}")
  message(FATAL_ERROR "chromium took no screenshot of ${PAGE} (exit ${status}):\n${out}\n${err}")
endif()
execute_process(COMMAND "${PROBE}" covers "${SCREENSHOT}" ${SHARE} ${COLOURS} RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the screenshot ${SCREENSHOT} of ${PAGE} does not show both colours ${COLOURS} on "
                      "${SHARE} of its pixels or more")
endif()
