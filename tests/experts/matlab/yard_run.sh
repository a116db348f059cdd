#!/bin/sh
# The geometry expert in Octave (modules/matlab/examples) takes part in a
# yard run through the bridge and the run writes exactly the data messages
# of the same run with the C++ geometry (beft-diff), also when it is killed
# mid-run and restarted; its --interface is the C++ expert's. Prints the
# runs' wall times. Skipped (77) without Octave,
# its Java interface or the client's jar.
#   yard_run.sh BIN_DIR SOURCE_DIR WORK_DIR JAR
bin="$1" source="$2" work="$3" jar="$4"
here="$(cd "$(dirname "$0")" && pwd)"
"$here/octave_ready.sh" "$jar" || exit $?
export BEFT_MATLAB_JAR="$jar" BEFT_BACKGROUND=0
octave="octave-cli --quiet --no-history --no-init-file $source/modules/matlab/run_expert.m"
geometry="$source/modules/matlab/examples/geometry_expert.m"
ticks=200

"$bin/beft-geometry" --interface >"$work.cpp-interface" &&
  $octave "$geometry" --interface >"$work.octave-interface" || exit 1
if ! cmp -s "$work.cpp-interface" "$work.octave-interface"; then
  echo "--interface of the Octave geometry differs from beft-geometry's:"
  diff "$work.cpp-interface" "$work.octave-interface"
  exit 1
fi

rm -rf "$work" && mkdir -p "$work" || exit 1
run() {  # run NAME [ARGS...]: a yard run into WORK/NAME, its wall time printed
  name="$1"
  shift
  start=$(date +%s%N)
  "$bin/beft-run" "$source/scenarios/yard.xml" --max-ticks $ticks --no-report --out "$work/$name" "$@" \
    >"$work/$name.out" 2>&1 || { echo "the $name run failed:"; cat "$work/$name.out"; exit 1; }
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  printf '%s: %d ticks of yard in %d.%03d s\n' "$name" $ticks $((ms / 1000)) $((ms % 1000))
}
run cpp
run octave --external "geometry=$octave $geometry"
run octave_killed --external "geometry=$octave $geometry" --kill geometry@60

if ! grep -q "\[geometry\] run ended" "$work/octave/processes.log"; then
  echo "the Octave geometry did not run to the end of the run:"
  grep "geometry" "$work/octave/processes.log" | tail -20
  exit 1
fi
if ! grep -q "\[geometry\] resumed from the run's history" "$work/octave_killed/processes.log"; then
  echo "the killed Octave geometry did not resume from the run's history:"
  grep "geometry" "$work/octave_killed/processes.log" | tail -20
  exit 1
fi
"$bin/beft-diff" "$work/cpp/run.lcmlog" "$work/octave/run.lcmlog" || exit 1
echo "killed at tick 60 and restarted:"
"$bin/beft-diff" "$work/cpp/run.lcmlog" "$work/octave_killed/run.lcmlog"
