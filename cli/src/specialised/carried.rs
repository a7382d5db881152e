//! The carried grid of generated evaluators and its dispatch from the library types.

use super::{Carried, Scalar};
use blossom::Point;
use blossom::{BezierCurve, TensorPatch, TriangularPatch};
use blossom::{PowerCurve, PowerSurface};

/// The carried evaluators, as `blossom::restriction!` generates them: `curve_N`,
/// `tensor_N_M`, `triangle_N_M`, generic over the ring `T` and the point dimension `D`.
pub mod grid {
    // `#[inline(never)]`: the grid is instantiated once, behind the `Scalar` dispatch, where
    // inlining the large evaluators gains nothing and cost a third more release build time.
    macro_rules! carry {
        (curve $dispatch:ident: $($n:tt => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = curve, degree = $n); )*
            /// The carried curve evaluator of degree `n` among those listed, coordinate by coordinate.
            pub(in crate::specialised) fn $dispatch<T: crate::specialised::Carried>(
                curve: &blossom::PowerCurve<T>,
                a: &T,
                b: &T,
            ) -> Option<blossom::BezierCurve<T>> {
                Some(match curve.degree() {
                    $($n => super::run_curve(curve.coefficients(), a, b, $name::<crate::specialised::Scalar, 1>),)*
                    _ => return None,
                })
            }
        };
        (bezier_curve $dispatch:ident: $($n:tt => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = bezier_curve, degree = $n); )*
            /// The carried Bézier-curve evaluator of degree `n` among those listed, coordinate by coordinate.
            pub(in crate::specialised) fn $dispatch<T: crate::specialised::Carried>(
                curve: &blossom::BezierCurve<T>,
                a: &T,
                b: &T,
            ) -> Option<blossom::BezierCurve<T>> {
                Some(match curve.degree() {
                    $($n => super::run_curve(curve.control_points(), a, b, $name::<crate::specialised::Scalar, 1>),)*
                    _ => return None,
                })
            }
        };
        (tensor $dispatch:ident: $(($n:tt, $m:tt) => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = tensor, degree = ($n, $m)); )*
            /// The carried tensor evaluator of bidegree `(n, m)` among those listed, coordinate by coordinate.
            pub(in crate::specialised) fn $dispatch<T: crate::specialised::Carried>(
                surface: &blossom::PowerSurface<T>,
                rect: &[T; 4],
            ) -> Option<blossom::TensorPatch<T>> {
                Some(match surface.degree() {
                    $(($n, $m) => super::run_tensor(surface, rect, $name::<crate::specialised::Scalar, 1>),)*
                    _ => return None,
                })
            }
        };
        (triangle $dispatch:ident: $(($n:tt, $m:tt) => $name:ident,)*) => {
            $( blossom::restriction!(#[inline(never)] vis = pub, name = $name, shape = triangle, degree = ($n, $m)); )*
            /// The carried triangle evaluator of degrees `(n, m)` among those listed, coordinate by coordinate.
            pub(in crate::specialised) fn $dispatch<T: crate::specialised::Carried>(
                surface: &blossom::PowerSurface<T>,
                tri: &[[T; 2]; 3],
            ) -> Option<blossom::TriangularPatch<T>> {
                Some(match surface.degree() {
                    $(($n, $m) => super::run_triangle(surface, tri, $name::<crate::specialised::Scalar, 1>),)*
                    _ => return None,
                })
            }
        };
    }

    // The degrees of the proof grid ([`crate::specialised::proof_table`]) and the others: the proofs
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

    // The degrees of the proof grid ([`crate::specialised::proof_table`]) and the others: the proofs
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

    // The degrees of the proof grid ([`crate::specialised::proof_table`]) and the others: the proofs
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
}

/// The evaluator signatures the dispatch calls (`D = 1`, on [`Scalar`]).
type CurveFn<const L: usize> = fn(&[[Scalar; 1]; L], &Scalar, &Scalar) -> [[Scalar; 1]; L];
type TensorFn<const R: usize, const C: usize> =
    fn(&[[[Scalar; 1]; C]; R], &[Scalar; 4]) -> [[[Scalar; 1]; C]; R];
type TriangleFn<const R: usize, const C: usize, const L: usize> =
    fn(&[[[Scalar; 1]; C]; R], &[[Scalar; 2]; 3]) -> [[Scalar; 1]; L];

/// Runs a curve evaluator (power coefficients or Bézier control points, `input`) coordinate
/// by coordinate.
// `x` is the coordinate taken from every input point at once; no iterator says that better.
#[allow(clippy::needless_range_loop)]
fn run_curve<T: Carried, const L: usize>(
    input: &[Point<T>],
    a: &T,
    b: &T,
    f: CurveFn<L>,
) -> BezierCurve<T> {
    let dim = input[0].len();
    let (a, b) = (a.wrap(), b.wrap());
    let mut points = vec![Vec::with_capacity(dim); L];
    for x in 0..dim {
        let coef: [[Scalar; 1]; L] = std::array::from_fn(|i| [input[i][x].wrap()]);
        for (p, [w]) in points.iter_mut().zip(f(&coef, &a, &b)) {
            p.push(T::unwrap(w));
        }
    }
    BezierCurve::new(points).expect("n + 1 points of one dimension")
}

fn surface_coordinate<T: Carried, const R: usize, const C: usize>(
    surface: &PowerSurface<T>,
    x: usize,
) -> [[[Scalar; 1]; C]; R] {
    let c = surface.coefficients();
    std::array::from_fn(|i| std::array::from_fn(|j| [c[i][j][x].wrap()]))
}

fn run_tensor<T: Carried, const R: usize, const C: usize>(
    surface: &PowerSurface<T>,
    rect: &[T; 4],
    f: TensorFn<R, C>,
) -> TensorPatch<T> {
    let dim = surface.dim();
    let rect = rect.each_ref().map(Carried::wrap);
    let mut net = vec![vec![Vec::with_capacity(dim); C]; R];
    for x in 0..dim {
        let out = f(&surface_coordinate(surface, x), &rect);
        for (net_row, out_row) in net.iter_mut().zip(out) {
            for (p, [w]) in net_row.iter_mut().zip(out_row) {
                p.push(T::unwrap(w));
            }
        }
    }
    TensorPatch::new(net).expect("a rectangular net")
}

fn run_triangle<T: Carried, const R: usize, const C: usize, const L: usize>(
    surface: &PowerSurface<T>,
    tri: &[[T; 2]; 3],
    f: TriangleFn<R, C, L>,
) -> TriangularPatch<T> {
    let dim = surface.dim();
    let tri = tri
        .each_ref()
        .map(|corner| corner.each_ref().map(Carried::wrap));
    let mut points = vec![Vec::with_capacity(dim); L];
    for x in 0..dim {
        for (p, [w]) in points
            .iter_mut()
            .zip(f(&surface_coordinate(surface, x), &tri))
        {
            p.push(T::unwrap(w));
        }
    }
    TriangularPatch::new(R + C - 2, points).expect("a full triangular net")
}

/// `curve` restricted to [a, b] by the generated evaluator of its degree (Theorem 1, eq. (3),
/// unrolled); `None` when that degree is not carried (see [`super::carried_degrees`]).
pub fn restrict_curve_specialised<T: Carried>(
    curve: &PowerCurve<T>,
    a: &T,
    b: &T,
) -> Option<BezierCurve<T>> {
    grid::curve_proved(curve, a, b).or_else(|| grid::curve_more(curve, a, b))
}

/// The Bézier curve `curve` over [0, 1] restricted to [a, b] by the generated Bézier-input
/// evaluator of its degree (forward differences, then eq. (3)); `None` when not carried.
pub fn restrict_bezier_curve_specialised<T: Carried>(
    curve: &BezierCurve<T>,
    a: &T,
    b: &T,
) -> Option<BezierCurve<T>> {
    grid::bezier_curve_carried(curve, a, b)
}

/// `surface` restricted to `rect = [a, b, c, d]` by the generated evaluator of its bidegree
/// (Theorem 2, eq. (9), unrolled); `None` when that bidegree is not carried.
pub fn restrict_tensor_specialised<T: Carried>(
    surface: &PowerSurface<T>,
    rect: &[T; 4],
) -> Option<TensorPatch<T>> {
    grid::tensor_proved(surface, rect).or_else(|| grid::tensor_more(surface, rect))
}

/// `surface`, of total degree N = n + m, restricted to the triangle `tri = [a, b, c]` by the
/// generated evaluator of its degrees (Theorem 3, eq. (14), unrolled); `None` when not carried.
pub fn restrict_triangle_specialised<T: Carried>(
    surface: &PowerSurface<T>,
    tri: &[[T; 2]; 3],
) -> Option<TriangularPatch<T>> {
    grid::triangle_proved(surface, tri).or_else(|| grid::triangle_more(surface, tri))
}
