# The command line: help, version, usage errors (exit code 2) and that
# doc/evgrid.md documents every option the program has.
source "$(dirname "$0")/lib.sh"

run 0 "$EVGRID" --help
for sub in build inspect export compare score-motion merge diff; do contains "$OUT" "  $sub "; done
run 0 "$EVGRID" --version
contains "$OUT" "evgrid "
run 2 "$EVGRID"
contains "$ERR" "Usage: evgrid <subcommand>"
run 2 "$EVGRID" frobnicate
contains "$ERR" "unknown subcommand 'frobnicate'"

for sub in build inspect export compare score-motion merge diff; do
  run 0 "$EVGRID" "$sub" --help
  contains "$OUT" "USAGE:"
  # Every option of --help appears in the manual, under the subcommand.
  for option in $(grep -oE -- '--[a-z][a-z_-]+' "$OUT" | sort -u); do
    case $option in --ignore_rest | --version | --help) continue ;; esac
    grep -qF -- "$option" "$EVGRID_DOC" || fail "doc/evgrid.md does not mention $sub $option"
  done
  run 2 "$EVGRID" "$sub" --no-such-option
  contains "$ERR" "evgrid $sub: error: unknown option or extra argument '--no-such-option'"
  contains "$ERR" "Try 'evgrid $sub --help'."
done

# Missing or senseless values: exit 2 before anything is read.
run 2 "$EVGRID" build -o "$T/out"
contains "$ERR" "missing the input"
run 2 "$EVGRID" build -i "$SENA"
contains "$ERR" "missing the output folder"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --every 0
contains "$ERR" "--every must be at least 1, got 0"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --every many
contains "$ERR" "bad value 'many' for --every"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --poses-format sometimes -p x.txt
contains "$ERR" "--poses-format must be auto, time or step"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --poses-format time
contains "$ERR" "--poses-format needs --poses"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --pose-tolerance -1 -p x.txt
contains "$ERR" "--pose-tolerance must be >= 0"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --animation --animation-size 12x12
contains "$ERR" "--animation-size must be WIDTHxHEIGHT"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --animation --animation-size 640
contains "$ERR" "--animation-size must be WIDTHxHEIGHT"
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --animation-every 5
contains "$ERR" "need --animation"
# OpenCV's AVI writer keeps whole rates of at least 1 frame a second.
for fps in 0.5 2.5 1001; do
  run 2 "$EVGRID" build -i "$SENA" -o "$T/out" --animation --animation-fps "$fps"
  contains "$ERR" "--animation-fps must be a whole number of frames per second, 1 to 1000, got $fps"
done
run 2 "$EVGRID" build -i "$SENA" -o "$T/out" extra-argument
contains "$ERR" "unknown option or extra argument 'extra-argument'"
[ ! -e "$T/out" ] || fail "a usage error created the output folder"

run 2 "$EVGRID" inspect
contains "$ERR" "missing the map file"
run 2 "$EVGRID" inspect map.evgrid --cell 1
contains "$ERR" "--cell must be X,Y"
run 2 "$EVGRID" inspect map.evgrid --cell 1,nan
contains "$ERR" "--cell must be X,Y"
run 2 "$EVGRID" export map.evgrid
contains "$ERR" "nothing to do"
run 2 "$EVGRID" export map.evgrid --png ""
contains "$ERR" "--png needs a non-empty value"
# An empty value is not the default, for every option of every subcommand.
run 2 "$EVGRID" score-motion -i x.rawlog --truth x.motion.gz --tolerance ""
contains "$ERR" "--tolerance needs a non-empty value"
run 2 "$EVGRID" build -i x.rawlog -o out --animation --animation-fps=
contains "$ERR" "--animation-fps needs a non-empty value"
echo "evgrid_cli: OK"
