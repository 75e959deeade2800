"""The solve runs without the GIL, two calls run at once, and Ctrl-C stops a solve cleanly.

No assertion here depends on the machine's speed: each observes an order of events (a barrier
that only concurrent calls pass, a counter that only a released GIL lets run, a signal sent once
the solve has reported progress), never a duration."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np

import norm_preserving
from conftest import mesh_path


def test_other_python_threads_run_during_a_solve(bunny):
    """With a switch interval longer than the test, a thread that holds the GIL is never made to
    give it up: the counter thread (which gives it up at every step, so the main thread can take
    it back) can only count while the main thread is inside texture() if the call released the
    GIL. Holding it would leave the count at most one or two."""
    done = threading.Event()
    count = [0]

    def counter():
        while not done.is_set():
            count[0] += 1
            time.sleep(0)  # gives the GIL up

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000)
    thread = threading.Thread(target=counter)
    try:
        thread.start()
        before = count[0]
        norm_preserving.texture(*bunny)
        during = count[0] - before
    finally:
        done.set()
        thread.join()
        sys.setswitchinterval(interval)
    assert during > 100


def test_two_threads_texture_two_meshes_at_once_with_the_same_bits(cow, cow_texture, bunny):
    """Each call's progress callback waits, at its first call, for the other's: a barrier that
    both pass only if both solves are under way at the same time (calls that held the GIL, or
    ran one after the other, would break it at its timeout). Running at once is what makes two
    calls faster than one after the other, on any machine with a core to spare; the uvs are
    those of the calls made alone."""
    meshes = {"cow": cow, "bunny": bunny}
    alone = {"cow": cow_texture[0], "bunny": norm_preserving.texture(*bunny)[0]}
    barrier = threading.Barrier(len(meshes), timeout=120)
    results, errors = {}, []

    def run(name):
        first = [True]

        def meet(progress):
            if first[0]:
                first[0] = False
                barrier.wait()

        try:
            results[name] = norm_preserving.texture(*meshes[name], progress=meet)[0]
        except Exception as e:  # raised again below, in the test's thread
            errors.append(e)

    threads = [threading.Thread(target=run, args=(name,)) for name in meshes]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for name in meshes:
        assert np.array_equal(results[name].view(np.uint64), alone[name].view(np.uint64))


# Run as a program of its own, which the test interrupts: textures bunny00 with a progress
# callback that tells the test where it is and, at its third call, waits for the SIGINT to have
# been handled (so that the solve cannot end first); then checks that nothing was written, that
# the arrays are intact and that the module still works, and lets the KeyboardInterrupt go.
INTERRUPTED_PROGRAM = textwrap.dedent("""
    import signal, sys, threading
    import numpy as np
    import norm_preserving

    vertices, faces = norm_preserving.read_mesh(sys.argv[1])
    copies = vertices.copy(), faces.copy()
    handled = threading.Event()

    def on_sigint(signum, frame):
        handled.set()
        signal.default_int_handler(signum, frame)  # raises KeyboardInterrupt

    signal.signal(signal.SIGINT, on_sigint)
    calls = []

    def progress(p):
        calls.append(p.fraction)
        print("progress", len(calls), flush=True)
        if len(calls) == 3:
            handled.wait(60)

    try:
        uv, report = norm_preserving.texture(vertices, faces, quality="exact", progress=progress)
        np.save(sys.argv[2], uv)
    except KeyboardInterrupt:
        print("interrupted after", len(calls), "progress calls", flush=True)
        assert np.array_equal(vertices, copies[0]) and np.array_equal(faces, copies[1])
        uv, report = norm_preserving.texture([[0, 0, 0], [1, 0, 0], [0, 1, 0.5]], [[0, 1, 2]])
        print("textured again:", np.isfinite(uv).all(), flush=True)
        raise
""")


def test_ctrl_c_interrupts_a_solve_cleanly(tmp_path):
    output = tmp_path / "uv.npy"
    child = subprocess.Popen([sys.executable, "-c", INTERRUPTED_PROGRAM, str(mesh_path("bunny00")), str(output)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=os.environ)
    lines = []
    for line in child.stdout:
        lines.append(line.strip())
        if line.strip() == "progress 3":
            child.send_signal(signal.SIGINT)
            break
    rest, errors = child.communicate(timeout=300)
    lines += rest.split("\n")
    # An uncaught KeyboardInterrupt ends Python by SIGINT, as the shell expects: not a crash.
    assert child.returncode == -signal.SIGINT, (child.returncode, errors)
    assert errors.rstrip().endswith("KeyboardInterrupt"), errors
    assert "interrupted after 3 progress calls" in lines  # no call once it stopped
    assert "textured again: True" in lines
    assert not output.exists()
