#!/usr/bin/env bash
# check_layers.sh SOURCE_DIR: the include rules of doc/architecture.md.
# Each layer includes only the layers below it; public headers include no
# private one; the programs use only public headers and the support target.
set -euo pipefail
cd "$1"
failures=0

# allow FILES_GLOB PATTERN WHAT: every #include of the files matches PATTERN.
allow() {
  local files=$1 pattern=$2 what=$3 file line
  for file in $files; do
    while IFS= read -r line; do
      if ! grep -qE "$pattern" <<<"$line"; then
        echo "$file: $line  ($what)"
        failures=$((failures + 1))
      fi
    done < <(grep -E '^\s*#\s*include' "$file" || true)
  done
}

# forbid FILES PATTERN WHAT: no #include of the files matches PATTERN.
forbid() {
  local files=$1 pattern=$2 what=$3 file line
  for file in $files; do
    while IFS= read -r line; do
      echo "$file: $line  ($what)"
      failures=$((failures + 1))
    done < <(grep -E '^\s*#\s*include' "$file" | grep -E "$pattern" || true)
  done
}

std='<[a-z_0-9]+(\.h)?>'
algebra='<mrpt_evidential/algebra/[A-Za-z]+\.h>'
vocabulary='<mrpt_evidential/TInvalidOption\.h>'
support='<mrpt_evidential/support/[A-Za-z]+\.h>'
lib=libmrpt_evidential

allow "$(ls $lib/algebra/include/mrpt_evidential/algebra/*.h)" \
  "^#include ($std|$algebra)" "the algebra: standard library and itself only"
allow "$lib/include/mrpt_evidential/TInvalidOption.h" \
  "^#include $std" "shared vocabulary: standard library only"
allow "$(ls $lib/include/mrpt_evidential/grid/*.h)" \
  "^#include ($std|$algebra|$vocabulary|<mrpt_evidential/grid/[A-Za-z]+\.h>)" \
  "grid: the algebra and itself, no MRPT"
allow "$(ls $lib/include/mrpt_evidential/scan/*.h)" \
  "^#include ($std|$algebra|$vocabulary|<mrpt_evidential/scan/[A-Za-z]+\.h>|<mrpt/)" \
  "scan: the algebra, MRPT and itself"
allow "$(ls $lib/include/mrpt_evidential/cloud/*.h)" \
  "^#include ($std|<mrpt_evidential/cloud/[A-Za-z]+\.h>)" "cloud's public header: its vocabulary only"
allow "$(ls $lib/include/mrpt_evidential/*.h)" \
  "^#include ($std|<mrpt/|<mrpt_evidential/)" "public headers: no private header"
forbid "$(ls $lib/include/mrpt_evidential/*.h $lib/include/mrpt_evidential/*/*.h)" \
  "<mrpt_evidential/support/" "public headers: not the support target"
allow "$(ls $lib/src/grid/*)" \
  "^#include ($std|$algebra|$vocabulary|$support|<mrpt_evidential/grid/|\"grid/)" "grid sources"
allow "$(ls $lib/src/scan/*)" \
  "^#include ($std|$algebra|$vocabulary|$support|<mrpt/|<mrpt_evidential/scan/|\"scan/)" "scan sources"
allow "$(ls $lib/src/cloud/*)" \
  "^#include ($std|$algebra|$support|<mrpt/|<mrpt_evidential/(scan|cloud)/|\"cloud/)" \
  "cloud sources: the scan layer below them"
allow "$(ls $lib/src/render/*)" \
  "^#include ($std|$support|<mrpt/img/|\"render/)" "render: images and the support target"
allow "$(ls $lib/src/insert/*)" \
  "^#include ($std|$algebra|$support|<mrpt/|<mrpt_evidential/(grid|scan)/|\"insert/)" \
  "insertion machinery: grid and scan below it"
allow "$(ls apps/*/*.cpp apps/*/*.h)" \
  "^#include ($std|<mrpt/|<opencv2/|<zlib\.h>|<tclap/|<sys/|<(unistd|fcntl)\.h>|<mrpt_evidential/|\"[A-Za-z]+\.h\")" \
  "programs: public headers, the support target and their own files"

if [ "$failures" -ne 0 ]; then
  echo "check_layers: $failures include(s) break the layering of doc/architecture.md"
  exit 1
fi
echo "check_layers: OK"
