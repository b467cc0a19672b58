#!/usr/bin/env bash
# Builds the C example (main.c) against the static library of the C ABI (capi/), runs it,
# and checks that its leg-1 force line is, character for character, the one Rust prints
# for the same simulation without the C ABI (capi/examples/leg1.rs). Runnable from any
# directory; CC and CARGO_TARGET_DIR are honoured.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
target="${CARGO_TARGET_DIR:-$root/target}"
out="$target/c-example"
mkdir -p "$out"

# The library, and the Rust side of the comparison in the same build (they share its graph).
cargo build --release -p symbody-capi --lib --example leg1
# What a Rust static library needs besides itself on Linux: rustc's list
# (`cargo rustc --release -p symbody-capi --lib --crate-type staticlib -- --print native-static-libs`).
native_libs=(-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc)
"${CC:-cc}" -std=c99 -pedantic -Wall -Wextra -Werror -I capi/include \
    -o "$out/main" examples/c/main.c "$target/release/libsymbody_c.a" "${native_libs[@]}"
# The header's extern "C" guards: it must also compile as C++.
if command -v c++ >/dev/null; then
    c++ -std=c++11 -Wall -Wextra -Werror -fsyntax-only -x c++ capi/include/symbody.h
fi

c_output="$("$out/main")"
printf '%s\n' "$c_output"
# = `cargo run --release -p symbody-capi --example leg1`, built above.
rust_line="$("$target/release/examples/leg1")"
c_line="$(printf '%s\n' "$c_output" | grep '^leg 1 force')"
if [[ "$c_line" != "$rust_line" ]]; then
    echo "C and Rust disagree:" >&2
    echo "  C:    $c_line" >&2
    echo "  Rust: $rust_line" >&2
    exit 1
fi
echo "C and Rust print the same leg 1 force." >&2
