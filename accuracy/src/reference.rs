//! The stable reference of the accuracy measurements: one plain f64 de Casteljau pyramid per
//! control point, written here from the textbook (x' = (1 - t) x + t y), sharing no code with
//! the library's engine.

/// The blossom b\[args\] of the Bézier curve `ctrl` by the textbook pyramid.
pub fn curve_point<const D: usize>(ctrl: &[[f64; D]], args: &[f64]) -> [f64; D] {
    let mut level = ctrl.to_vec();
    for (r, &t) in args.iter().enumerate() {
        for i in 0..level.len() - 1 - r {
            let (x, y) = (level[i], level[i + 1]);
            level[i] = std::array::from_fn(|k| (1.0 - t) * x[k] + t * y[k]);
        }
    }
    level[0]
}

/// q_j = b[a^(n-j), b^j] for every j, one pyramid each.
pub fn curve<const D: usize>(ctrl: &[[f64; D]], a: f64, b: f64) -> Vec<[f64; D]> {
    let n = ctrl.len() - 1;
    (0..=n)
        .map(|j| {
            let args: Vec<f64> = (0..n).map(|k| if k < n - j { a } else { b }).collect();
            curve_point(ctrl, &args)
        })
        .collect()
}

/// p_(ν μ) = b[a^(n-ν), b^ν; c^(m-μ), d^μ] of the net `net` (row by row, `cols` points per
/// row), each by the textbook pyramid along v in every row, then along u.
pub fn tensor<const D: usize>(net: &[[f64; D]], cols: usize, rect: [f64; 4]) -> Vec<[f64; D]> {
    let [a, b, c, d] = rect;
    let (n, m) = (net.len() / cols - 1, cols - 1);
    let mut out = Vec::with_capacity(net.len());
    for nu in 0..=n {
        let us: Vec<f64> = (0..n).map(|k| if k < n - nu { a } else { b }).collect();
        for mu in 0..=m {
            let vs: Vec<f64> = (0..m).map(|k| if k < m - mu { c } else { d }).collect();
            let column: Vec<[f64; D]> = net.chunks(cols).map(|row| curve_point(row, &vs)).collect();
            out.push(curve_point(&column, &us));
        }
    }
    out
}

/// q_(ν μ λ) = b[A^ν, B^μ, C^λ] of the triangular net `net` (degree `n`, lexicographic order of
/// (ν, μ)), corners in affine coordinates (s, t) with weights (s, t, 1 - s - t), each by the
/// textbook barycentric pyramid.
pub fn triangle<const D: usize>(
    net: &[[f64; D]],
    n: usize,
    corners: [[f64; 2]; 3],
) -> Vec<[f64; D]> {
    let index = |d: usize, i: usize, j: usize| i * (d + 1) - i * i.saturating_sub(1) / 2 + j;
    let mut out = Vec::with_capacity(net.len());
    for nu in 0..=n {
        for mu in 0..=n - nu {
            let args = (0..n).map(|k| {
                if k < nu {
                    corners[0]
                } else if k < nu + mu {
                    corners[1]
                } else {
                    corners[2]
                }
            });
            let mut level = net.to_vec();
            for (r, [s, t]) in args.enumerate() {
                let w = 1.0 - s - t;
                let d = n - r - 1;
                for i in 0..=d {
                    for j in 0..=d - i {
                        let (pa, pb, pc) = (
                            level[index(d + 1, i + 1, j)],
                            level[index(d + 1, i, j + 1)],
                            level[index(d + 1, i, j)],
                        );
                        level[index(d, i, j)] =
                            std::array::from_fn(|x| s * pa[x] + t * pb[x] + w * pc[x]);
                    }
                }
            }
            out.push(level[0]);
        }
    }
    out
}
