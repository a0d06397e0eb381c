#!/usr/bin/env bash
# check_links.sh SOURCE_DIR: every relative link of README.md and doc/ leads to
# a file that exists, and every #anchor to a heading of its file, as GitHub
# names them (lower case, punctuation dropped, spaces to hyphens, -1, -2 on
# repeats). Code blocks are left out.
set -euo pipefail
export LC_ALL=C
cd "$1"
failures=0

# outside_code FILE: the file's lines outside ``` blocks.
outside_code() { awk '/^```/ { code = !code; next } !code' "$1"; }

# anchors FILE: the anchor of each heading, one a line.
anchors() {
  outside_code "$1" | sed -nE 's/^#{1,6} +//p' | tr 'A-Z' 'a-z' |
    sed -E 's/[^a-z0-9 _-]//g; s/ /-/g' |
    awk '{ seen[$0]++; print (seen[$0] > 1 ? $0 "-" (seen[$0] - 1) : $0) }'
}

while IFS= read -r file; do
  dir=$(dirname "$file")
  while IFS= read -r link; do
    [[ $link =~ ^[a-z]+: ]] && continue  # http:, https:, mailto:
    path=${link%%#*}
    fragment=
    [[ $link == *"#"* ]] && fragment=${link#*#}
    target=$file
    [[ -n $path ]] && target=$dir/$path
    if [[ ! -e $target ]]; then
      echo "$file: ($link): no such file"
      failures=$((failures + 1))
    elif [[ -n $fragment && $target == *.md ]] && ! anchors "$target" | grep -qxF "$fragment"; then
      echo "$file: ($link): no such heading"
      failures=$((failures + 1))
    fi
  done < <(outside_code "$file" | grep -oE '\]\([^) ]+\)' | sed -E 's/^\]\((.*)\)$/\1/')
done < <(find README.md doc -name '*.md' | sort)

echo "$failures broken links"
[[ $failures -eq 0 ]]
