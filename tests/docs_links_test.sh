#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every relative link and image of README.md and docs/**/*.md names a file or folder that exists
# (a plot spliced with the wrong prefix, a renamed page). Web addresses and in-page anchors are
# not checked; "path#anchor" is checked for the path. Prints "FILE:LINE: TARGET" for each broken one.
set -u
root=${1:?usage: docs_links_test.sh PROJECT_ROOT}
status=0
while IFS= read -r page; do
  dir=$(dirname "$page")
  # ](target) and ](target "title"), outside fenced code blocks
  while IFS=: read -r line target; do
    path=${target%%#*}
    [ -z "$path" ] && continue
    case $path in http://* | https://* | mailto:*) continue ;; esac
    if [ ! -e "$dir/$path" ]; then
      echo "${page#"$root"/}:$line: broken link '$target'"
      status=1
    fi
  done < <(awk '/^[[:space:]]*```/ { fenced = !fenced; next }
                !fenced { line = $0
                  while (match(line, /\]\([^) ]+/)) {
                    print FNR ":" substr(line, RSTART + 2, RLENGTH - 2)
                    line = substr(line, RSTART + RLENGTH) } }' "$page")
done < <(find "$root/README.md" "$root/docs" -name '*.md' | sort)
exit $status
