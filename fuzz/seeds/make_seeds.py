#!/usr/bin/env python3
"""Writes the hand-written seeds of fuzz/corpus/ (run from anywhere; idempotent).

job_entry: the option byte (bit 0 f64, bits 1-3 method, 7 = default; bits 4-5 --max-work;
bit 6 small --max-input; bit 7 --flag=value) then one job of every kind of docs/cli.md.
number_reader: numbers of the grammar of cli/src/number.rs and its edge cases.
restrict_shapes: one input per shape kind, exact and f64 (see cli/src/fuzzing.rs).
"""
import json, os, hashlib

here = os.path.dirname(os.path.abspath(__file__))
corpus = os.path.join(here, "..", "corpus")

def put(target, name, data):
    d = os.path.join(corpus, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "seed-" + name), "wb") as f:
        f.write(data)

tri = [[0, 0], [1, 0], [0, 1]]
jobs = {
    "curve": {"kind": "curve", "coefficients": [[1, "1/2"], [0, "-3/4"], ["2", "0.125"]], "interval": ["1/3", 2]},
    "curve-1d": {"kind": "curve", "coefficients": [[0], [0], [0], [1]], "interval": [1, 2]},
    "tensor": {"kind": "tensor", "coefficients": [[[1], [2]], [[3], ["-1/2"]]], "rectangle": [0, 1, "1/2", 2]},
    "triangle": {"kind": "triangle", "coefficients": [[[1], [2]], [[3], [4]]], "triangle": tri},
    "triangle-total": {"kind": "triangle", "total_degree": 2, "coefficients": [[[1], [0], [1]], [[2], [3]], [[5]]], "triangle": [[1, 0], [0, 1], [0, 0]]},
    "bezier-curve": {"kind": "bezier-curve", "control_points": [[0, 0], [1, 2], [3, 3], [4, 0]], "interval": [0, "1/2"]},
    "bezier-tensor": {"kind": "bezier-tensor", "control_points": [[[0], [1]], [[2], [3]]], "rectangle": [0, "1/2", "1/4", 1]},
    "bezier-triangle": {"kind": "bezier-triangle", "control_points": [
        {"a": 1, "b": 0, "c": 0, "point": [1, 0]}, {"a": 0, "b": 1, "c": 0, "point": [0, 1]},
        {"a": 0, "b": 0, "c": 1, "point": [0, 0]}],
        "triangle": [["1/2", "1/2", 0], [0, "1/2", "1/2"], ["1/2", 0, "1/2"]]},
    "derivative": {"kind": "derivative", "control_points": [[0], [1], [3], [7]], "order": 2},
    "bspline": {"kind": "bspline", "degree": 2, "pieces": [
        {"interval": [0, 1], "coefficients": [0, 0, 1]},
        {"interval": [1, 2], "coefficients": [-1, 2, 0]}]},
    "bspline-eval": {"kind": "bspline-eval", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2],
                     "control_points": [[0], [1], [3], [4]], "at": [0, "1/2", 1, 2]},
    "rational-curve": {"kind": "rational-curve", "numerator": [[1, 0], [0, 2], [-1, 0]],
                       "denominator": [1, 0, 1], "interval": [0, 1], "degree": 3},
    "elevate": {"kind": "elevate", "control_points": [[0], [1], [0]], "to_degree": 4},
    "reduce-interpolating": {"kind": "reduce", "control_points": [[0], [1], [0], [2]], "to_degree": 2, "method": "interpolating"},
    "reduce-least-squares": {"kind": "reduce", "control_points": [[0], [1], [0], [2]], "to_degree": 1, "method": "least-squares"},
    "reduce-endpoints": {"kind": "reduce", "control_points": [[0], [1], [0], [2]], "to_degree": 2, "method": "least-squares-endpoints"},
    "rational-tensor": {"kind": "rational-tensor", "numerator": [[[1], [2]], [[0], [1]]],
                        "denominator": [[1, 0], [1, 0]], "rectangle": [0, 1, 0, 1], "degree": [2, 1]},
    "rational-triangle": {"kind": "rational-triangle", "numerator": [[[1], [2]], [[3]]],
                          "denominator": [[1, 0], [1]], "triangle": tri, "total_degree": 1},
    "big-numbers": {"kind": "curve", "coefficients": [["1e100"], ["-1e-100"]], "interval": ["123456789012345678901234567890", "1/7"]},
    "f64-json-numbers": {"kind": "curve", "coefficients": [[0.1], [1e300], [2.5e-3]], "interval": [0.5, 1.5]},
}
# Options: default method (index 7) under exact and f64, plus each method on the curve.
for name, job in jobs.items():
    text = json.dumps(job).encode()
    put("job_entry", name + "-exact", bytes([7 << 1]) + text)
    put("job_entry", name + "-f64", bytes([(7 << 1) | 1]) + text)
for k in range(7):
    text = json.dumps(jobs["tensor"]).encode()
    put("job_entry", "tensor-method%d-exact" % k, bytes([k << 1]) + text)
    put("job_entry", "tensor-method%d-f64" % k, bytes([(k << 1) | 1 | 0x80]) + text)
# Budget and input-limit refusals, bad input.
put("job_entry", "max-work-0", bytes([(2 << 4) | (7 << 1)]) + json.dumps(jobs["curve"]).encode())
put("job_entry", "max-input", bytes([0x40 | (7 << 1)]) + json.dumps(jobs["bspline-eval"]).encode() * 3)
for name, text in {
    "malformed": b'{"kind": "curve",',
    "bom": b'\xef\xbb\xbf{"kind": "curve", "coefficients": [[1]], "interval": [0, 1]}',
    "bad-utf8": b'{"kind": "\xff"}',
    "unknown-kind": b'{"kind": "foo"}',
    "huge-exponent": b'{"kind": "curve", "coefficients": [["1e100000"]], "interval": [0, "1e-100000"]}',
    "zero-denominator": b'{"kind": "curve", "coefficients": [["1/0"]], "interval": [0, 1]}',
    "ragged": b'{"kind": "tensor", "coefficients": [[[1, 2], [3, 4]], [[5, 6], [7]]], "rectangle": [0, 1, 0, 1]}',
    "not-object": b'[1, 2, 3]',
}.items():
    put("job_entry", name + "-exact", bytes([7 << 1]) + text)
    put("job_entry", name + "-f64", bytes([(7 << 1) | 1]) + text)

for k, text in enumerate([
    "0", "-7", "+7", "007", "-0", "3/4", "-22/7", "6/8", "0/5", "1/0", "0.125", "-1e-3", "2.5E+3",
    ".5", "5.", "1e100000", "1e100001", "1e-100000", "0e999999999", "1e999999999", "1e-999999999",
    "1e400", "-1e400", "4.9e-324", "2.4703282292062328e-324", "9007199254740993",
    "1.7976931348623157e308", "1.7976931348623158e308", "1" + "0" * 400 + "/3",
    "1" + "0" * 400 + "/1" + "0" * 399, "inf", "NaN", "", " 1", "1/-2", "--1", "1.5/2",
    "123456789012345678901234567890", "0.1", "1e", "e5", "1/2/3", "\u0661", "0x10",
]):
    put("number_reader", "%02d" % k, text.encode())

def shape(mode, kind, dim, n, m, rest):
    return bytes([mode, kind, dim, n, m]) + bytes(rest)
# mode: 0 exact, 1 f64; kind 0..6; dim-1; degrees; then numbers.
for kind in range(7):
    nums = [(i * 37 + 11) % 256 for i in range(200)]
    put("restrict_shapes", "exact-kind%d" % kind, shape(0, kind, 1, 3, 2, nums))
    put("restrict_shapes", "f64-kind%d" % kind, shape(1, kind, 1, 3, 2, nums))
    put("restrict_shapes", "f64-raw-kind%d" % kind, shape(1, kind, 0, 2, 1, [0] + [0x40, 0, 0, 0, 0, 0, 0xf0, 0x7f] * 40))
