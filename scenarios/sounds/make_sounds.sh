#!/usr/bin/env bash
# Regenerates the scenario sounds: mono, 16 kHz, 16-bit WAV files of 1-3 s,
# made with espeak-ng (speech) and sox (sirens, engines, fire). The results are
# committed, so nothing needs generating at build time; run this only to change
# them. sox runs in repeatable mode (-R) so the noise is the same every time.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")"
for tool in espeak-ng sox; do
  command -v "$tool" >/dev/null || { echo "make_sounds.sh: $tool is not installed" >&2; exit 1; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

FORMAT=(-r 16000 -c 1 -b 16)
SOX=(sox -R -D -V1)
MAX_SECONDS=2.8

# speak OUT SPEED VOICE TEXT [extra sox effects...]: speech, trimmed of
# leading/trailing silence, normalised, at most MAX_SECONDS long.
speak() {
  local out="$1" speed="$2" voice="$3" text="$4"
  shift 4
  espeak-ng -v "$voice" -s "$speed" -w "$work/speech.wav" "$text"
  "${SOX[@]}" "$work/speech.wav" "${FORMAT[@]}" "$out" \
    silence 1 0.02 1% reverse silence 1 0.02 1% reverse "$@" trim 0 "$MAX_SECONDS" gain -n -1
}

# A person calling for help.
speak help.wav 175 en+m3 "Help! Help me! I am here!"
# Calm conversation of someone walking.
speak talk.wav 150 en+f3 "It is fine, just keep walking with me."
# A radio announcer, band-limited like a small loudspeaker.
speak voice_radio.wav 170 en-us+m1 "Good evening, this is the news on radio one." sinc 300-3400

# Two-tone siren: 960 Hz and 770 Hz, 0.4 s each, three times.
"${SOX[@]}" -n "${FORMAT[@]}" "$work/high.wav" synth 0.4 sine 960 fade 0.01 0.4 0.01
"${SOX[@]}" -n "${FORMAT[@]}" "$work/low.wav" synth 0.4 sine 770 fade 0.01 0.4 0.01
"${SOX[@]}" "$work/high.wav" "$work/low.wav" "$work/high.wav" "$work/low.wav" \
  "$work/high.wav" "$work/low.wav" "${FORMAT[@]}" siren.wav gain -n -1

# Idling engine: the firing rhythm (27 Hz, four cylinders at 800 rpm) and its
# harmonics up to 2 kHz, the lowest ones taken down as a car's body radiates
# them little, plus mechanical noise around 1 kHz pulsing with the firing.
# Most of its energy lies between 80 Hz and 1.5 kHz, where ears localise.
"${SOX[@]}" -n "${FORMAT[@]}" "$work/harmonics.wav" synth 2.5 sawtooth 27 highpass 90 highpass 90 lowpass 2000 gain -n -3
"${SOX[@]}" -n "${FORMAT[@]}" "$work/mechanics.wav" synth 2.5 pinknoise bandpass 900 1.2k tremolo 27 60 gain -n -9
"${SOX[@]}" -m "$work/harmonics.wav" "$work/mechanics.wav" "${FORMAT[@]}" engine.wav fade 0.05 2.5 0.05 gain -n -1

# Fire: a roar of turbulent flames (pink noise, 100-700 Hz, swelling at 3 Hz),
# bright crackles (bursts of noise above 1.2 kHz at irregular times) and a
# faint hiss above 2 kHz: broadband, unlike the engine.
"${SOX[@]}" -n "${FORMAT[@]}" "$work/roar.wav" synth 2.5 pinknoise highpass 100 lowpass 700 tremolo 3 40 gain -n -16
crackles=()
i=0
for step in "0.05 0.012" "0.09 0.006" "0.03 0.02" "0.12 0.008" "0.04 0.015" "0.07 0.006" "0.02 0.01" \
            "0.1 0.012" "0.06 0.008" "0.03 0.018" "0.08 0.006" "0.05 0.01" "0.11 0.015" "0.04 0.007" \
            "0.06 0.012" "0.02 0.006" "0.09 0.02" "0.05 0.008" "0.07 0.012" "0.03 0.006" "0.1 0.01" \
            "0.04 0.015" "0.06 0.007" "0.08 0.012" "0.03 0.01"; do
  read -r gap burst <<<"$step"
  "${SOX[@]}" -n "${FORMAT[@]}" "$work/gap$i.wav" trim 0 "$gap"
  "${SOX[@]}" -n "${FORMAT[@]}" "$work/burst$i.wav" synth "$burst" whitenoise highpass 1200 fade 0 "$burst" "$burst"
  crackles+=("$work/gap$i.wav" "$work/burst$i.wav")
  i=$((i + 1))
done
"${SOX[@]}" "${crackles[@]}" "${FORMAT[@]}" "$work/crackle.wav" pad 0 1
"${SOX[@]}" -n "${FORMAT[@]}" "$work/hiss.wav" synth 2.5 whitenoise highpass 2000 gain -n -22
"${SOX[@]}" -m "$work/roar.wav" "$work/crackle.wav" "$work/hiss.wav" "${FORMAT[@]}" fire.wav trim 0 2.5 gain -n -1

for file in help talk voice_radio siren engine fire; do
  printf '%-16s %s s\n' "$file.wav" "$(soxi -D "$file.wav")"
done
