#!/bin/bash
# Instructions per curve of each form at each degree (callgrind, 10,000 curves, each restricted
# to its own random sub-interval of [0, 1] and the answer summed; set-up removed):
#   ./count.sh                                  3-D, textbook and the three library forms
#   DIM=2 DEGREES="2 3" FORMS="lyon kurbo textbook curve bezier into" ./count.sh
# Build first: cargo build --release --bin count.
bin=${CARGO_TARGET_DIR:-target}/release/count
dim=${DIM:-3}
forms=${FORMS:-textbook curve bezier into}
ir() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$@" 2>&1 | sed -n 's/.*Collected : //p'; }
printf '| %s-D degree |' "$dim"; for f in $forms; do printf ' %s |' "$f"; done; echo
printf '|---|'; for f in $forms; do printf -- '---|'; done; echo
for d in ${DEGREES:-3 5 8 12 16 24 32 64}; do
  row="| $d"
  for f in $forms; do
    z=$(ir "$f" "$d" 0 "$dim"); t=$(ir "$f" "$d" 10 "$dim")
    row="$row | $(( (t - z) / 10000 ))"
  done
  echo "$row |"
done
