#!/bin/sh
# The conformance test (conformance.js): the pinned packages installed with
# npm ci into the build directory, then the checks. Exit 77 (skipped) with
# the reason when node or the packages are missing.
#   run_conformance.sh SOURCE_DIR WORK_DIR BIN_DIR REPOSITORY_ROOT
src="$1"; work="$2"; bin="$3"; root="$4"
command -v node >/dev/null 2>&1 || { echo "skipped: node is not installed (apt-get install nodejs npm)"; exit 77; }
command -v npm >/dev/null 2>&1 || { echo "skipped: npm is not installed (apt-get install npm)"; exit 77; }
mkdir -p "$work" || exit 1
cp "$src"/package.json "$src"/package-lock.json "$src"/*.js "$work"/ || exit 1
if ! cmp -s "$src/package-lock.json" "$work/node_modules/.installed-lock.json"; then
  if ! (cd "$work" && npm ci --ignore-scripts --no-audit --no-fund >npm-ci.log 2>&1); then
    echo "skipped: npm ci could not install the pinned packages (offline?); see $work/npm-ci.log:"
    tail -5 "$work/npm-ci.log"
    exit 77
  fi
  cp "$src/package-lock.json" "$work/node_modules/.installed-lock.json"
fi
rm -rf "$work/out"
exec node "$work/conformance.js" "$bin" "$root" "$work/out"
