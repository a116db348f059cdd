#!/bin/sh
# Whether the MATLAB/Octave client can run here: octave-cli, its Java
# interface and the client's jar. Exits 0, or 77 (a skipped test) saying
# what is missing.
#   octave_ready.sh JAR
jar="$1"
if ! command -v octave-cli >/dev/null 2>&1; then
  echo "skipped: octave-cli is not installed (apt-get install octave)"
  exit 77
fi
if [ -z "$jar" ] || [ ! -f "$jar" ]; then
  echo "skipped: the client's jar was not built (javac missing: apt-get install default-jdk-headless, then rebuild)"
  exit 77
fi
if ! octave-cli --quiet --no-history --no-init-file --eval 'exit(~usejava("jvm"))' >/dev/null 2>&1; then
  echo "skipped: Octave's Java interface does not start (no JVM found: apt-get install default-jdk-headless)"
  exit 77
fi
exit 0
