#!/bin/sh
# Instructions per certified boolean, counted by callgrind (repeatable on a loaded machine,
# unlike wall time): the 200 quadratic triangle pairs of benches/region_peers/src/shapes.rs
# over 100 passes (regions kept), and the 8 + 8 cubic stars over 200 runs. Prints the
# inclusive count of `triangle_intersection` / `boolean` divided by the number of calls.
# Needs valgrind. Run from the repository root: sh benches/region_count.sh
set -eu
target="${CARGO_TARGET_DIR:-target}"
cargo build --release -p blossom --example region_profile >/dev/null 2>&1
out="$(mktemp -d)"
valgrind --tool=callgrind --callgrind-out-file="$out/t" "$target/release/examples/region_profile" triangles 100 >/dev/null 2>&1
valgrind --tool=callgrind --callgrind-out-file="$out/s" "$target/release/examples/region_profile" stars 200 >/dev/null 2>&1
count() { callgrind_annotate --inclusive=yes "$1" | grep "$2 \[" | head -1 | awk -v n="$3" '{gsub(",", "", $1); printf "%.0f", $1 / n}'; }
echo "triangle pair: $(count "$out/t" 'region::boolean::triangle_intersection' 20000) instructions per boolean"
echo "8+8 stars: $(count "$out/s" 'region::boolean::boolean' 200) instructions per boolean"
rm -r "$out"
