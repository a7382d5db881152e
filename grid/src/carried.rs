//! The carried grid of generated evaluators and its dispatch from the library types.
//!
//! Every evaluator is instantiated once, on [`Scalar`] with `D = 1`, inside a *non-generic*
//! dispatch function per list of degrees (`curve_proved`, `tensor_more`, ...). Non-generic
//! functions are compiled in this crate only; the generic entry points
//! ([`restrict_curve_specialised`], ...) merely convert each coordinate to [`Scalar`] and call
//! them. So a crate (a test, the binary) that calls the entry points with any number type
//! compiles none of the grid again: before this split every such crate re-instantiated all of
//! it, because generic code is monomorphised where it is used.

use crate::{Carried, Scalar};
use blossom::Point;
use blossom::{BezierCurve, PowerCurve, PowerSurface, PowerTriangle, TensorPatch, TriangularPatch};

/// One coordinate of a curve's input (power coefficients or control points), and the answer.
type CurveColumn = dyn Fn(&[Scalar], &Scalar, &Scalar) -> Option<Vec<Scalar>>;

/// The carried evaluators, as `blossom::restriction!` generates them: `curve_N`,
/// `tensor_N_M`, `triangle_N_M`, generic over the ring `T` and the point dimension `D`, and
/// their dispatch on [`Scalar`] coordinates.
pub mod grid {
    use crate::Scalar;

    // `#[inline(never)]`: the grid is instantiated once, behind the `Scalar` dispatch, where
    // inlining the large evaluators gains nothing and cost a third more release build time.
    macro_rules! carry {
        (curve $dispatch:ident: $($n:tt => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = curve, degree = $n); )*
            carry!(@curve_dispatch $dispatch: $($n => $name,)*);
        };
        (bezier_curve $dispatch:ident: $($n:tt => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = bezier_curve, degree = $n); )*
            carry!(@curve_dispatch $dispatch: $($n => $name,)*);
        };
        (@curve_dispatch $dispatch:ident: $($n:tt => $name:ident,)*) => {
            /// One coordinate of a curve of degree `input.len() - 1` by the carried evaluator of
            /// that degree among those listed; `None` when it is not among them.
            #[inline(never)]
            pub fn $dispatch(input: &[Scalar], a: &Scalar, b: &Scalar) -> Option<Vec<Scalar>> {
                Some(match input.len().checked_sub(1)? {
                    $($n => {
                        let coef = std::array::from_fn(|i| [input[i].clone()]);
                        $name::<Scalar, 1>(&coef, a, b).into_iter().map(|[w]| w).collect()
                    })*
                    _ => return None,
                })
            }
        };
        (tensor $dispatch:ident: $(($n:tt, $m:tt) => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = tensor, degree = ($n, $m)); )*
            /// One coordinate of a tensor patch (`input[i][j]`) by the carried evaluator of its
            /// bidegree among those listed; `None` when it is not among them.
            #[inline(never)]
            pub fn $dispatch(input: &[Vec<Scalar>], rect: &[Scalar; 4]) -> Option<Vec<Vec<Scalar>>> {
                let degree = (input.len().checked_sub(1)?, input[0].len().checked_sub(1)?);
                Some(match degree {
                    $(($n, $m) => {
                        let coef = std::array::from_fn(|i| std::array::from_fn(|j| [input[i][j].clone()]));
                        $name::<Scalar, 1>(&coef, rect)
                            .into_iter()
                            .map(|row| row.into_iter().map(|[w]| w).collect())
                            .collect()
                    })*
                    _ => return None,
                })
            }
        };
        (bezier_tensor $dispatch:ident: $(($n:tt, $m:tt) => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = bezier_tensor, degree = ($n, $m)); )*
            /// One coordinate of a Bézier net (`input[i][j]`) by the carried evaluator of its
            /// bidegree among those listed; `None` when it is not among them.
            #[inline(never)]
            pub fn $dispatch(input: &[Vec<Scalar>], rect: &[Scalar; 4]) -> Option<Vec<Vec<Scalar>>> {
                let degree = (input.len().checked_sub(1)?, input[0].len().checked_sub(1)?);
                Some(match degree {
                    $(($n, $m) => {
                        let ctrl = std::array::from_fn(|i| std::array::from_fn(|j| [input[i][j].clone()]));
                        $name::<Scalar, 1>(&ctrl, rect)
                            .into_iter()
                            .map(|row| row.into_iter().map(|[w]| w).collect())
                            .collect()
                    })*
                    _ => return None,
                })
            }
        };
        (bezier_triangle $dispatch:ident: $($n:tt => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = bezier_triangle, degree = $n); )*
            /// One coordinate of a triangular Bézier net of degree `degree` (in the order of
            /// `blossom::TriangularPatch`) by the carried evaluator of that degree among those
            /// listed; `None` when it is not among them.
            #[inline(never)]
            pub fn $dispatch(degree: usize, input: &[Scalar], tri: &[[Scalar; 2]; 3]) -> Option<Vec<Scalar>> {
                Some(match degree {
                    $($n => {
                        let ctrl = std::array::from_fn(|k| [input[k].clone()]);
                        $name::<Scalar, 1>(&ctrl, tri).into_iter().map(|[w]| w).collect()
                    })*
                    _ => return None,
                })
            }
        };
        (triangle_total $dispatch:ident: $($n:tt => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = triangle_total, degree = $n); )*
            /// One coordinate of a triangular array of total degree `degree` (rows one after
            /// the other) on a triangle by the carried evaluator of that degree among those
            /// listed; `None` when it is not among them.
            #[inline(never)]
            pub fn $dispatch(degree: usize, input: &[Scalar], tri: &[[Scalar; 2]; 3]) -> Option<Vec<Scalar>> {
                Some(match degree {
                    $($n => {
                        let coef = std::array::from_fn(|k| [input[k].clone()]);
                        $name::<Scalar, 1>(&coef, tri).into_iter().map(|[w]| w).collect()
                    })*
                    _ => return None,
                })
            }
        };
        (triangle $dispatch:ident: $(($n:tt, $m:tt) => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = triangle, degree = ($n, $m)); )*
            /// One coordinate of a surface (`input[i][j]`) on a triangle by the carried
            /// evaluator of its degrees among those listed; `None` when it is not among them.
            #[inline(never)]
            pub fn $dispatch(input: &[Vec<Scalar>], tri: &[[Scalar; 2]; 3]) -> Option<Vec<Scalar>> {
                let degree = (input.len().checked_sub(1)?, input[0].len().checked_sub(1)?);
                Some(match degree {
                    $(($n, $m) => {
                        let coef = std::array::from_fn(|i| std::array::from_fn(|j| [input[i][j].clone()]));
                        $name::<Scalar, 1>(&coef, tri).into_iter().map(|[w]| w).collect()
                    })*
                    _ => return None,
                })
            }
        };
    }

    // The degrees of the proof grid (`blossom_cli::specialised::proof_table`) and the others: the proofs
    // instantiate only the first list with symbolic polynomials.
    carry! { curve curve_proved:
    1 => curve_1,
    2 => curve_2,
    3 => curve_3,
    4 => curve_4,
    5 => curve_5,
    6 => curve_6,
    7 => curve_7,
    8 => curve_8,
    9 => curve_9,
    10 => curve_10,
    }

    // Bézier input (forward differences, then eq. (3)): the degrees `bezier-curve` jobs use.
    carry! { bezier_curve bezier_curve_carried:
    1 => bezier_curve_1,
    2 => bezier_curve_2,
    3 => bezier_curve_3,
    4 => bezier_curve_4,
    5 => bezier_curve_5,
    6 => bezier_curve_6,
    7 => bezier_curve_7,
    8 => bezier_curve_8,
    9 => bezier_curve_9,
    10 => bezier_curve_10,
    11 => bezier_curve_11,
    12 => bezier_curve_12,
    13 => bezier_curve_13,
    14 => bezier_curve_14,
    15 => bezier_curve_15,
    16 => bezier_curve_16,
    }

    carry! { curve curve_more:
    11 => curve_11,
    12 => curve_12,
    13 => curve_13,
    14 => curve_14,
    15 => curve_15,
    16 => curve_16,
    }

    // The degrees of the proof grid (`blossom_cli::specialised::proof_table`) and the others: the proofs
    // instantiate only the first list with symbolic polynomials.
    carry! { tensor tensor_proved:
    (1, 1) => tensor_1_1,
    (1, 2) => tensor_1_2,
    (1, 3) => tensor_1_3,
    (1, 4) => tensor_1_4,
    (2, 1) => tensor_2_1,
    (2, 2) => tensor_2_2,
    (2, 3) => tensor_2_3,
    (2, 4) => tensor_2_4,
    (3, 1) => tensor_3_1,
    (3, 2) => tensor_3_2,
    (3, 3) => tensor_3_3,
    (3, 4) => tensor_3_4,
    (4, 1) => tensor_4_1,
    (4, 2) => tensor_4_2,
    (4, 3) => tensor_4_3,
    (4, 4) => tensor_4_4,
    }

    carry! { tensor tensor_more:
    (0, 1) => tensor_0_1,
    (0, 2) => tensor_0_2,
    (0, 3) => tensor_0_3,
    (0, 4) => tensor_0_4,
    (0, 5) => tensor_0_5,
    (1, 0) => tensor_1_0,
    (1, 5) => tensor_1_5,
    (2, 0) => tensor_2_0,
    (2, 5) => tensor_2_5,
    (3, 0) => tensor_3_0,
    (3, 5) => tensor_3_5,
    (4, 0) => tensor_4_0,
    (4, 5) => tensor_4_5,
    (5, 0) => tensor_5_0,
    (5, 1) => tensor_5_1,
    (5, 2) => tensor_5_2,
    (5, 3) => tensor_5_3,
    (5, 4) => tensor_5_4,
    (5, 5) => tensor_5_5,
    }

    // The degrees of the proof grid (`blossom_cli::specialised::proof_table`) and the others: the proofs
    // instantiate only the first list with symbolic polynomials.
    carry! { triangle triangle_proved:
    (1, 1) => triangle_1_1,
    (1, 2) => triangle_1_2,
    (1, 3) => triangle_1_3,
    (2, 1) => triangle_2_1,
    (2, 2) => triangle_2_2,
    (2, 3) => triangle_2_3,
    (3, 1) => triangle_3_1,
    (3, 2) => triangle_3_2,
    (3, 3) => triangle_3_3,
    }

    carry! { triangle triangle_more:
    (0, 1) => triangle_0_1,
    (0, 2) => triangle_0_2,
    (0, 3) => triangle_0_3,
    (0, 4) => triangle_0_4,
    (1, 0) => triangle_1_0,
    (1, 4) => triangle_1_4,
    (2, 0) => triangle_2_0,
    (2, 4) => triangle_2_4,
    (3, 0) => triangle_3_0,
    (3, 4) => triangle_3_4,
    (4, 0) => triangle_4_0,
    (4, 1) => triangle_4_1,
    (4, 2) => triangle_4_2,
    (4, 3) => triangle_4_3,
    (4, 4) => triangle_4_4,
    }

    // Triangular arrays of a given total degree (`"total_degree"` on a `triangle` job).
    carry! { triangle_total triangle_total_carried:
    1 => triangle_total_1,
    2 => triangle_total_2,
    3 => triangle_total_3,
    4 => triangle_total_4,
    5 => triangle_total_5,
    6 => triangle_total_6,
    }

    // Bézier input of the `bezier-tensor` and `bezier-triangle` jobs (de Casteljau's steps
    // with shared work, the runtime engine's order).
    carry! { bezier_tensor bezier_tensor_carried:
    (0, 1) => bezier_tensor_0_1,
    (0, 2) => bezier_tensor_0_2,
    (0, 3) => bezier_tensor_0_3,
    (0, 4) => bezier_tensor_0_4,
    (1, 0) => bezier_tensor_1_0,
    (1, 1) => bezier_tensor_1_1,
    (1, 2) => bezier_tensor_1_2,
    (1, 3) => bezier_tensor_1_3,
    (1, 4) => bezier_tensor_1_4,
    (2, 0) => bezier_tensor_2_0,
    (2, 1) => bezier_tensor_2_1,
    (2, 2) => bezier_tensor_2_2,
    (2, 3) => bezier_tensor_2_3,
    (2, 4) => bezier_tensor_2_4,
    (3, 0) => bezier_tensor_3_0,
    (3, 1) => bezier_tensor_3_1,
    (3, 2) => bezier_tensor_3_2,
    (3, 3) => bezier_tensor_3_3,
    (3, 4) => bezier_tensor_3_4,
    (4, 0) => bezier_tensor_4_0,
    (4, 1) => bezier_tensor_4_1,
    (4, 2) => bezier_tensor_4_2,
    (4, 3) => bezier_tensor_4_3,
    (4, 4) => bezier_tensor_4_4,
    }

    carry! { bezier_triangle bezier_triangle_carried:
    1 => bezier_triangle_1,
    2 => bezier_triangle_2,
    3 => bezier_triangle_3,
    4 => bezier_triangle_4,
    5 => bezier_triangle_5,
    6 => bezier_triangle_6,
    }
}

/// Runs a curve dispatch (power coefficients or Bézier control points, `input`) coordinate
/// by coordinate; `None` when the degree is not carried.
fn run_curve<T: Carried>(
    input: &[Point<T>],
    a: &T,
    b: &T,
    column: &CurveColumn,
) -> Option<BezierCurve<T>> {
    let dim = input[0].len();
    let (a, b) = (a.wrap(), b.wrap());
    let mut points = vec![Vec::with_capacity(dim); input.len()];
    for x in 0..dim {
        let coef: Vec<Scalar> = input.iter().map(|p| p[x].wrap()).collect();
        for (p, w) in points.iter_mut().zip(column(&coef, &a, &b)?) {
            p.push(T::unwrap(w));
        }
    }
    Some(BezierCurve::new(points).expect("n + 1 points of one dimension"))
}

/// Coordinate `x` of every coefficient of `surface`, as scalars.
fn surface_coordinate<T: Carried>(surface: &PowerSurface<T>, x: usize) -> Vec<Vec<Scalar>> {
    surface
        .coefficients()
        .iter()
        .map(|row| row.iter().map(|c| c[x].wrap()).collect())
        .collect()
}

/// `curve` restricted to [a, b] by the generated evaluator of its degree (Theorem 1, eq. (3),
/// unrolled); `None` when that degree is not carried (see `blossom_cli::specialised::carried_degrees`).
pub fn restrict_curve_specialised<T: Carried>(
    curve: &PowerCurve<T>,
    a: &T,
    b: &T,
) -> Option<BezierCurve<T>> {
    run_curve(&curve.coefficients().to_vec(), a, b, &|c, a, b| {
        grid::curve_proved(c, a, b).or_else(|| grid::curve_more(c, a, b))
    })
}

/// The Bézier curve `curve` over [0, 1] restricted to [a, b] by the generated Bézier-input
/// evaluator of its degree; `None` when not carried.
pub fn restrict_bezier_curve_specialised<T: Carried>(
    curve: &BezierCurve<T>,
    a: &T,
    b: &T,
) -> Option<BezierCurve<T>> {
    run_curve(
        &curve.control_points().to_vec(),
        a,
        b,
        &grid::bezier_curve_carried,
    )
}

/// `surface` restricted to `rect = [a, b, c, d]` by the generated evaluator of its bidegree
/// (Theorem 2, eq. (9), unrolled); `None` when that bidegree is not carried.
pub fn restrict_tensor_specialised<T: Carried>(
    surface: &PowerSurface<T>,
    rect: &[T; 4],
) -> Option<TensorPatch<T>> {
    let (n, m) = surface.degree();
    let rect = rect.each_ref().map(Carried::wrap);
    let mut net = vec![vec![Vec::with_capacity(surface.dim()); m + 1]; n + 1];
    for x in 0..surface.dim() {
        let coef = surface_coordinate(surface, x);
        let out = grid::tensor_proved(&coef, &rect).or_else(|| grid::tensor_more(&coef, &rect))?;
        for (net_row, out_row) in net.iter_mut().zip(out) {
            for (p, w) in net_row.iter_mut().zip(out_row) {
                p.push(T::unwrap(w));
            }
        }
    }
    Some(TensorPatch::new(net).expect("a rectangular net"))
}

/// `surface`, of total degree N = n + m, restricted to the triangle `tri = [a, b, c]` by the
/// generated evaluator of its degrees (Theorem 3, eq. (14), unrolled); `None` when not carried.
pub fn restrict_triangle_specialised<T: Carried>(
    surface: &PowerSurface<T>,
    tri: &[[T; 2]; 3],
) -> Option<TriangularPatch<T>> {
    let (n, m) = surface.degree();
    let tri = tri
        .each_ref()
        .map(|corner| corner.each_ref().map(Carried::wrap));
    let mut points = vec![Vec::with_capacity(surface.dim()); blossom::engine::triangle_len(n + m)];
    for x in 0..surface.dim() {
        let coef = surface_coordinate(surface, x);
        let out =
            grid::triangle_proved(&coef, &tri).or_else(|| grid::triangle_more(&coef, &tri))?;
        for (p, w) in points.iter_mut().zip(out) {
            p.push(T::unwrap(w));
        }
    }
    Some(TriangularPatch::new(n + m, points).expect("a full triangular net"))
}

/// The Bézier patch `patch` over [0, 1]^2 restricted to `rect = [a, b, c, d]` by the generated
/// Bézier-input evaluator of its bidegree; `None` when not carried.
pub fn restrict_bezier_tensor_specialised<T: Carried>(
    patch: &TensorPatch<T>,
    rect: &[T; 4],
) -> Option<TensorPatch<T>> {
    let (n, m) = patch.degree();
    let dim = patch.dim();
    let rect = rect.each_ref().map(Carried::wrap);
    let mut net = vec![vec![Vec::with_capacity(dim); m + 1]; n + 1];
    for x in 0..dim {
        let ctrl: Vec<Vec<Scalar>> = patch
            .rows()
            .map(|row| row.iter().map(|p| p[x].wrap()).collect())
            .collect();
        let out = grid::bezier_tensor_carried(&ctrl, &rect)?;
        for (net_row, out_row) in net.iter_mut().zip(out) {
            for (p, w) in net_row.iter_mut().zip(out_row) {
                p.push(T::unwrap(w));
            }
        }
    }
    Some(TensorPatch::new(net).expect("a rectangular net"))
}

/// The triangular Bézier patch `patch` restricted to the sub-triangle with corners `tri`, each
/// given by its first two barycentric coordinates, by the generated Bézier-input evaluator of
/// its degree; `None` when not carried.
pub fn restrict_bezier_triangle_specialised<T: Carried>(
    patch: &TriangularPatch<T>,
    tri: &[[T; 2]; 3],
) -> Option<TriangularPatch<T>> {
    let big_n = patch.degree();
    let dim = patch.control_points()[0].len();
    let tri = tri
        .each_ref()
        .map(|corner| corner.each_ref().map(Carried::wrap));
    let mut points = vec![Vec::with_capacity(dim); patch.control_points().len()];
    for x in 0..dim {
        let ctrl: Vec<Scalar> = patch.control_points().iter().map(|p| p[x].wrap()).collect();
        let out = grid::bezier_triangle_carried(big_n, &ctrl, &tri)?;
        for (p, w) in points.iter_mut().zip(out) {
            p.push(T::unwrap(w));
        }
    }
    Some(TriangularPatch::new(big_n, points).expect("a full triangular net"))
}

/// `surface`, a triangular array of total degree N, restricted to the triangle `tri` by the
/// generated evaluator of its degree (eq. (14) over the array, unrolled); `None` when not
/// carried, or when the array is not a full triangular array (a grid taken at degree N).
pub fn restrict_power_triangle_specialised<T: Carried>(
    surface: &PowerTriangle<T>,
    tri: &[[T; 2]; 3],
) -> Option<TriangularPatch<T>> {
    let big_n = surface.degree();
    if !surface.is_triangular() {
        return None;
    }
    let tri = tri
        .each_ref()
        .map(|corner| corner.each_ref().map(Carried::wrap));
    let mut points = vec![Vec::with_capacity(surface.dim()); blossom::engine::triangle_len(big_n)];
    for x in 0..surface.dim() {
        let coef: Vec<Scalar> = surface
            .coordinates()
            .iter()
            .skip(x)
            .step_by(surface.dim())
            .map(Carried::wrap)
            .collect();
        let out = grid::triangle_total_carried(big_n, &coef, &tri)?;
        for (p, w) in points.iter_mut().zip(out) {
            p.push(T::unwrap(w));
        }
    }
    Some(TriangularPatch::new(big_n, points).expect("a full triangular net"))
}
