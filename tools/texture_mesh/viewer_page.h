// Writes a web page that shows a glb model, textured and rotatable with the mouse, in any browser
// with WebGL and offline: one self-contained HTML file that inlines three.js with its GLTFLoader
// and OrbitControls (Debian's libjs-three, read when the page is written) and the glb itself.

#ifndef NP_EXAMPLES_VIEWER_PAGE_H
#define NP_EXAMPLES_VIEWER_PAGE_H

#include <array>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace np_examples {

// The scripts the page inlines, relative to three.js's directory, in the order they run.
inline std::array<std::string, 3> viewer_scripts()
{
  return {"three.min.js", "examples/js/loaders/GLTFLoader.js", "examples/js/controls/OrbitControls.js"};
}

// Why the page cannot be written with the three.js of `three_directory`, if it cannot.
inline std::optional<std::string> viewer_scripts_problem(const std::string& three_directory)
{
  for(const std::string& script : viewer_scripts())
    if(!std::ifstream(three_directory + "/" + script))
      return "cannot read " + three_directory + "/" + script + " (Debian's libjs-three provides it)";
  return std::nullopt;
}

inline std::string base64(const std::vector<unsigned char>& bytes)
{
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for(std::size_t i = 0; i < bytes.size(); i += 3)
  {
    const std::size_t left = bytes.size() - i;
    const unsigned long group = (unsigned long)bytes[i] << 16 | (left > 1 ? (unsigned long)bytes[i + 1] << 8 : 0) |
                                (left > 2 ? bytes[i + 2] : 0);
    text += digits[(group >> 18) & 63];
    text += digits[(group >> 12) & 63];
    text += left > 1 ? digits[(group >> 6) & 63] : '=';
    text += left > 2 ? digits[group & 63] : '=';
  }
  return text;
}

// The page's own script: the model fills the view, lit from the camera, and turns with the
// mouse (left: rotate, wheel: zoom, right: pan); it is drawn only when something changes.
inline const char* viewer_script()
{
  return R"(
const message = document.getElementById('message');
try {
  const bytes = atob(document.getElementById('model').textContent.trim());
  const glb = new Uint8Array(bytes.length);
  for (let i = 0; i < bytes.length; ++i) glb[i] = bytes.charCodeAt(i);
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.gammaOutput = true;
  renderer.gammaFactor = 2.2;
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  document.body.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x404040);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x707070, 0.8));
  const camera = new THREE.PerspectiveCamera(35, window.innerWidth / window.innerHeight, 0.01, 100);
  const headlight = new THREE.DirectionalLight(0xffffff, 0.5);
  headlight.position.set(0.3, 0.5, 1);
  camera.add(headlight);
  scene.add(camera);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  const render = () => renderer.render(scene, camera);
  controls.addEventListener('change', render);
  window.addEventListener('resize', () => {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    render();
  });
  // Looks at the model's box from the front, right and above, from just far enough that each
  // corner of the box is in view.
  const frame = (box) => {
    const center = box.getCenter(new THREE.Vector3());
    const toward = new THREE.Vector3(0.5, 0.35, 1).normalize();
    camera.position.copy(center).add(toward);
    camera.lookAt(center);
    camera.updateMatrixWorld();
    const right = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
    const up = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
    const tanV = Math.tan(camera.fov / 2 * Math.PI / 180), tanH = tanV * camera.aspect;
    let distance = 0;
    for (let corner = 0; corner < 8; ++corner) {
      const d = new THREE.Vector3(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                  corner & 4 ? box.max.z : box.min.z).sub(center);
      distance = Math.max(distance, d.dot(toward) + Math.max(Math.abs(d.dot(right)) / tanH, Math.abs(d.dot(up)) / tanV));
    }
    distance = distance > 0 ? 1.05 * distance : 1;
    camera.position.copy(center).addScaledVector(toward, distance);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
  };
  new THREE.GLTFLoader().parse(glb.buffer, '', (gltf) => {
    scene.add(gltf.scene);
    frame(new THREE.Box3().setFromObject(gltf.scene));
    message.textContent = 'drag to turn, scroll to zoom, right-drag to pan';
    render();
  }, (error) => { message.textContent = 'cannot show the model: ' + error; });
} catch (error) {
  message.textContent = 'cannot show the model (this page needs WebGL): ' + error.message;
}
)";
}

// `code` made safe to inline in a <script> element: every "<!--", "<script" and "</script",
// in any case, which would end the element early or change how the HTML parser reads on (the
// HTML standard's "restrictions for contents of script elements"), gets its '<' written as
// "\x3C", which means '<' in a string, a template or a regular expression (where three.js has
// them) and changes nothing in a comment.
inline std::string inline_script(const std::string& code)
{
  auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
  auto follows = [&](std::size_t at, const char* word) {
    for(std::size_t k = 0; word[k] != '\0'; ++k)
      if(at + k >= code.size() || lower(code[at + k]) != word[k])
        return false;
    return true;
  };
  std::string safe;
  safe.reserve(code.size());
  for(std::size_t at = 0; at < code.size(); ++at)
    if(code[at] == '<' && (follows(at + 1, "!--") || follows(at + 1, "script") || follows(at + 1, "/script")))
      safe += "\\x3C";
    else
      safe += code[at];
  return safe;
}

// Writes the page `path`, titled `title`, that shows the model `glb` with the three.js of
// `three_directory`.
inline bool write_viewer_page(const std::string& path, const std::string& title, const std::vector<unsigned char>& glb,
                              const std::string& three_directory)
{
  std::string escaped_title;
  for(char c : title)
    escaped_title += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
  std::ofstream page(path, std::ios::binary);
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escaped_title
       << "</title>\n<style>html, body { margin: 0; height: 100%; overflow: hidden; background: #404040; }\n"
       << "#message { position: absolute; left: 8px; bottom: 6px; color: #ddd; font: 13px sans-serif; }</style>\n"
       << "</head>\n<body>\n<div id=\"message\">loading " << escaped_title << "...</div>\n";
  for(const std::string& script : viewer_scripts())
  {
    std::ifstream in(three_directory + "/" + script, std::ios::binary);
    const std::string code((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if(!in.good() && !in.eof())
      return false;
    page << "<script>\n" << inline_script(code) << "\n</script>\n";
  }
  page << "<script type=\"application/octet-stream\" id=\"model\">" << base64(glb) << "</script>\n"
       << "<script>" << inline_script(viewer_script()) << "</script>\n</body>\n</html>\n";
  return bool(page);
}

} // namespace np_examples

#endif
