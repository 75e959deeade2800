// Validates glb files with the Khronos glTF validator (the npm package gltf-validator), run by
// Node.js:
//   node validate_glb.js <the gltf-validator package's directory> FILE...
// Prints each file's issues; exits with 1 if any file has an error or a warning (or cannot be
// validated). Infos and hints are printed, and pass.

const fs = require('fs');
const path = require('path');
const validator = require(path.resolve(process.argv[2]));

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)),
                                               { uri: file, maxIssues: 0, writeTimestamp: false });
  const issues = report.issues;
  const counts = report.info ? `; ${report.info.totalVertexCount} vertices, ${report.info.totalTriangleCount} triangles` : '';
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos, ` +
              `${issues.numHints} hints (glTF validator ${validator.version()})${counts}`);
  for (const message of issues.messages) {
    const where = message.pointer !== undefined ? ` at ${message.pointer}` :
                  message.offset !== undefined ? ` at byte ${message.offset}` : '';
    console.log(`  ${['error', 'warning', 'info', 'hint'][message.severity]} ${message.code}${where}: ${message.message}`);
  }
  return issues.numErrors === 0 && issues.numWarnings === 0;
}

(async () => {
  let valid = process.argv.length > 3;
  for (const file of process.argv.slice(3)) {
    try {
      valid = (await validate(file)) && valid;
    } catch (error) {
      console.log(`${file}: cannot be validated: ${error}`);
      valid = false;
    }
  }
  process.exit(valid ? 0 : 1);
})();
