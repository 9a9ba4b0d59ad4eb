#!/usr/bin/env bash
# Validates a .glb (Khronos glTF validator) and renders it in headless Chromium (three.js).
# Usage: bash .ci/viewer/check.sh <file.glb> <out.png>
# Installs what it needs: the npm packages (npm ci), Debian's chromium (apt-get).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if [ $# -ne 2 ]; then
  echo "usage: $0 <file.glb> <out.png>" >&2
  exit 2
fi
glb="$1" png="$2"

if ! command -v npm >/dev/null 2>&1 || ! command -v node >/dev/null 2>&1; then
  echo "viewer check SKIPPED: npm/node not found (glb validation and render not run)"
  exit 0
fi

if [ ! -d "$here/node_modules" ]; then
  echo "--- npm ci in $here"
  (cd "$here" && npm ci --no-audit --no-fund)
fi

echo "--- validate $glb"
if ! node "$here/validate.mjs" "$glb"; then
  echo "viewer check FAILED: the glTF validator reports errors in $glb" >&2
  exit 1
fi

chromium="${CHROMIUM:-/usr/bin/chromium}"
if [ ! -x "$chromium" ]; then
  echo "--- installing Debian's chromium (not found at $chromium)"
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo -n)
  if ! { "${sudo[@]}" apt-get update -qq &&
         "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium; } ||
     [ ! -x "$chromium" ]; then
    echo "viewer check FAILED: could not install chromium with apt-get (needed for the render)" >&2
    exit 1
  fi
fi

echo "--- render $glb -> $png"
CHROMIUM="$chromium" node "$here/render.mjs" "$glb" "$png"
