#!/bin/bash
# Instructions per curve of each form at each degree (callgrind, 10,000 curves, set-up removed).
bin=${CARGO_TARGET_DIR:-target}/release/count
ir() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$@" 2>&1 | sed -n 's/.*Collected : //p'; }
printf '| degree | textbook | BezierCurve::subsegment | Bezier::subsegment | subsegment_into |\n|---|---|---|---|---|\n'
for d in ${DEGREES:-3 5 8 12 16 24 32 64}; do
  row="| $d"
  for f in textbook curve bezier into; do
    z=$(ir $f $d 0); t=$(ir $f $d 10)
    row="$row | $(( (t - z) / 10000 ))"
  done
  echo "$row |"
done
