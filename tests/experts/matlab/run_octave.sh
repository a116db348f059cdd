#!/bin/sh
# Runs one Octave test function of this folder (it returns its number of
# failed checks) with the client's jar; skipped (77) without Octave, its
# Java interface or the jar.
#   run_octave.sh JAR TEST_FUNCTION
here="$(cd "$(dirname "$0")" && pwd)"
"$here/octave_ready.sh" "$1" || exit $?
BEFT_MATLAB_JAR="$1" exec octave-cli --quiet --no-history --no-init-file \
  --eval "addpath('$here'); exit($2() > 0)"
