#!/usr/bin/env bash
# Installs what building and testing take on Debian 12, as root: the packages of
# doc/debian-packages.txt (the build) and doc/debian-test-packages.txt (the real clients the tests
# run: Blender, Chromium, pytest), and Node.js with npm for the Khronos glTF validator, which
# the tests fetch from the npm registry. A machine that already has a Node.js with npm (such as
# NodeSource's, with which Debian's npm package conflicts) keeps it.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
apt-get update
xargs -a doc/debian-packages.txt apt-get install -y
xargs -a doc/debian-test-packages.txt apt-get install -y
if ! command -v npm > /dev/null; then
  apt-get install -y nodejs npm
fi
# The Khronos glTF validator, which the tests run on every glb the tool writes.
npm install -g --ignore-scripts gltf-validator@2.0.0-dev.3.10
