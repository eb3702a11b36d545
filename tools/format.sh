#!/usr/bin/env bash
# The code's format (.clang-format, clang-format 14) over every C++ file in git.
#   tools/format.sh            applies it (make format)
#   tools/format.sh --check D  changes nothing; writes D/format.xml (JUnit: one case, failed naming the files that differ)
#                              and exits 1 when a file differs (make test)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cf=$(command -v clang-format-14 || command -v clang-format) || { echo "format: clang-format not found"; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" != "--check" ]; then
  "$cf" --style=file -i "${files[@]}"
  exit 0
fi
out=${2:?"--check needs a results directory"}
mkdir -p "$out"
differ=()
for f in "${files[@]}"; do
  "$cf" --style=file "$f" | cmp -s - "$f" || differ+=("$f")
done
failure=""
if [ ${#differ[@]} -gt 0 ]; then
  printf 'format: %s differs from .clang-format (make format)\n' "${differ[@]}"
  failure="<failure message=\"${#differ[@]} files not in the .clang-format format (make format): ${differ[*]:0:20}\"/>"
fi
printf '%s\n' '<?xml version="1.0" encoding="UTF-8"?>' \
  "<testsuites><testsuite name=\"format\" tests=\"1\"><testcase name=\"clang_format\" classname=\"format\">$failure</testcase></testsuite></testsuites>" \
  >"$out/format.xml"
echo "format: ${#files[@]} files, ${#differ[@]} not formatted"
[ ${#differ[@]} = 0 ]
