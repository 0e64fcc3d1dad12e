#!/usr/bin/env bash
# Builds libquadsect.a and libquadsect.so, compiles the C and C++ examples
# (example.c, example.cpp, and components.c: the typed components of
# natural pairs), the hostile-input test and the C example of the README's
# "C and C++" section (as written, at most 15 lines) against each of them with gcc
# (C99) and g++ (C++11), runs them, compares their output with the
# expected files, and runs them under valgrind --leak-check=full (leaks and
# memory errors fail) when valgrind is installed.  Prints "examples: N
# passed, M failed"; exits non-zero on any failure.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
target="${CARGO_TARGET_DIR:-$root/target}"
lib="$target/release"

cargo build --release --quiet -p quadsect-capi --manifest-path "$root/Cargo.toml"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAILED: $*"; }

# The README's example: the ```c block after <!-- example: readme.c --> and
# its output, the ```text block after <!-- output: readme.c -->.
readme="$root/README.md"
block_after() {
  awk -v marker="$1" '
    index($0, marker) == 1 { found = 1; next }
    found && /^```/ { if (inside) exit; inside = 1; next }
    inside { print }
  ' "$readme"
}
block_after "<!-- example: readme.c -->" > "$work/readme.c"
block_after "<!-- output: readme.c -->" > "$work/readme.txt"
if [ ! -s "$work/readme.c" ] || [ ! -s "$work/readme.txt" ]; then
  fail "README.md lacks the marked C example or its output"
fi
lines=$(wc -l < "$work/readme.c")
if [ "$lines" -le 15 ]; then pass; else fail "the README's C example has $lines lines (at most 15)"; fi

cflags=(-std=c99 -Wall -Wextra -pedantic -Werror -g -I "$here/include")
cxxflags=(-std=c++11 -Wall -Wextra -pedantic -Werror -g -I "$here/include")

# build NAME COMPILER SOURCE FLAGS…: NAME-static and NAME-shared
build() {
  local name="$1" cc="$2" src="$3"
  shift 3
  # static: the archive and the system libraries Rust's std needs
  if "$cc" "$@" "$src" "$lib/libquadsect.a" -lpthread -ldl -lm -o "$work/$name-static"; then
    pass
  else
    fail "$name: static link"
  fi
  # shared: -lquadsect finds libquadsect.so (preferred over the .a); -lm
  # for the examples' own use of <math.h>
  if "$cc" "$@" "$src" -L "$lib" -lquadsect -lm -Wl,-rpath,"$lib" -o "$work/$name-shared"; then
    if ldd "$work/$name-shared" > "$work/ldd.txt" && grep -q "libquadsect.so" "$work/ldd.txt"; then
      pass
    else
      fail "$name: not linked to libquadsect.so"
    fi
  else
    fail "$name: shared link"
  fi
}

# check NAME EXPECTED-FILE (or - to check only the exit status)
check() {
  local name="$1" expected="$2" kind status
  for kind in static shared; do
    local bin="$work/$name-$kind"
    [ -x "$bin" ] || continue # its build failed (counted there)
    status=0
    "$bin" > "$work/out.txt" 2>&1 || status=$?
    if [ "$status" -eq 0 ]; then
      if [ "$expected" = - ] || diff -u "$expected" "$work/out.txt"; then
        pass
      else
        fail "$name ($kind): output differs from $expected"
      fi
    else
      cat "$work/out.txt"
      fail "$name ($kind): exit status $status"
    fi
    if command -v valgrind > /dev/null 2>&1; then
      if valgrind -q --leak-check=full --error-exitcode=1 "$bin" > /dev/null 2> "$work/valgrind.txt"; then
        pass
      else
        cat "$work/valgrind.txt"
        fail "$name ($kind): valgrind"
      fi
    fi
  done
}

build example gcc "$here/examples/example.c" "${cflags[@]}"
build example_cpp g++ "$here/examples/example.cpp" "${cxxflags[@]}"
build components gcc "$here/examples/components.c" "${cflags[@]}"
build hostile gcc "$here/examples/hostile.c" "${cflags[@]}"
build readme gcc "$work/readme.c" "${cflags[@]}"
# the header alone compiles as C++11 too (extern "C" guards)
if printf '#include "quadsect.h"\nint main() { return qs_version() == nullptr; }\n' |
  g++ "${cxxflags[@]}" -x c++ - -x none "$lib/libquadsect.a" -lpthread -ldl -lm -o "$work/cxx-header"; then
  pass
else
  fail "quadsect.h does not compile as C++11"
fi

check example "$here/examples/expected/example.txt"
check example_cpp "$here/examples/expected/example_cpp.txt"
check components "$here/examples/expected/components.txt"
check hostile -
check readme "$work/readme.txt"

if ! command -v valgrind > /dev/null 2>&1; then
  echo "note: valgrind not installed; memory checks skipped"
fi
echo "examples: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
