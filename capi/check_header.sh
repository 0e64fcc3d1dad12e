#!/usr/bin/env bash
# Checks that the committed include/quadsect.h equals a fresh generation by
# cbindgen from capi/src with capi/cbindgen.toml.  `--write` regenerates
# it instead.  Installs the pinned cbindgen (cargo install --locked) when
# the one on PATH is missing or another version: header text can differ
# between cbindgen versions.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
version="0.29.4"

cbindgen=""
if command -v cbindgen >/dev/null 2>&1 && [ "$(cbindgen --version)" = "cbindgen $version" ]; then
  cbindgen="$(command -v cbindgen)"
else
  tools="${CARGO_TARGET_DIR:-$root/target}/tools"
  if [ ! -x "$tools/bin/cbindgen" ] || [ "$("$tools/bin/cbindgen" --version)" != "cbindgen $version" ]; then
    echo "installing cbindgen $version into $tools" >&2
    cargo install cbindgen --version "=$version" --locked --root "$tools" --quiet
  fi
  cbindgen="$tools/bin/cbindgen"
fi

fresh="$(mktemp)"
trap 'rm -f "$fresh"' EXIT
(cd "$here" && "$cbindgen" --quiet --config cbindgen.toml --crate quadsect-capi --output "$fresh" .)

if [ "${1:-}" = "--write" ]; then
  cp "$fresh" "$here/include/quadsect.h"
  echo "wrote capi/include/quadsect.h"
elif diff -u "$here/include/quadsect.h" "$fresh"; then
  echo "capi/include/quadsect.h is up to date (cbindgen $version)"
else
  echo "capi/include/quadsect.h is stale: run capi/check_header.sh --write and commit it" >&2
  exit 1
fi
