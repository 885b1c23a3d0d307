#!/bin/sh
# Fails if a C++ source of the project is not formatted as .clang-format says (installs
# clang-format if missing). `sh scripts/check_format.sh --fix` formats them in place.
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_dependencies.sh" clang-format
cd "$root"
files=$(find include examples tools test benchmarks fuzz python -name '*.h' -o -name '*.cpp' 2>/dev/null |
        grep -v '^test/hostile/' | sort)
if [ "$1" = "--fix" ]; then
  clang-format -i $files
else
  clang-format --dry-run --Werror $files
  echo "format: $(echo "$files" | wc -l) files as .clang-format says"
fi
