//! A piecewise polynomial surface on a grid as a tensor-product B-spline surface:
//! Curry-Schoenberg (Theorem 2.4 of seed 002) in each variable, with the de Boor points of
//! Theorem 2.2 as tensor blossoms of the pieces.
//!
//! The pieces F_ij of bidegree <= (p, q) live on the cells [u_i, u_{i+1}] x [v_j, v_{j+1}] of
//! breakpoints u_0 < ... < u_K and v_0 < ... < v_L. Across the line u = u_i the surface has the
//! exact order of continuity r_i = min_j r_ij, where r_ij is the highest r with
//! ∂^k F_{i-1,j} / ∂u^k = ∂^k F_ij / ∂u^k on the line for k = 0..r (-1 when the values differ
//! already). Written as polynomials in u whose coefficients are polynomials in v (a row of the
//! coefficient grid flattened into one long point), this is the curve's exact continuity
//! ([`super::continuity_at`]) of two long-point curves at u_i, because polynomials in v agree
//! on an interval exactly when their coefficients agree. The same holds in v with the columns.
//! The u knots repeat u_0 and u_K p + 1 times and u_i exactly p - r_i times (a line where
//! every row of cells is one polynomial disappears), and likewise in v. The de Boor points are
//!
//! d_kl = f_ij(t_{k+1}, ..., t_{k+p}; s_{l+1}, ..., s_{l+q})
//!
//! for any knot cell (σ, τ) with σ - p <= k <= σ and τ - q <= l <= τ, f_ij the tensor blossom
//! (eqs. (7)-(8) of the subdivision paper) of the piece on that cell. That the multiplicities
//! make every such cell give the same point is the tensor-product form of Theorem 2.4: the
//! piecewise polynomials with these continuities are the tensor product of the two spline
//! spaces, and on a fixed row or column the statement is the curve's.

use super::curry_schoenberg::continuity_at;
use super::surface::BSplineSurface;
use crate::error::{Error, ErrorKind, Result};
use crate::num::linalg::{check_all_finite, Field};
use crate::restrict::definition::tensor_blossom;
use crate::shape::point::{flatten, Point};
use crate::shape::power::{PowerCurve, PowerSurface};
use std::cmp::Ordering;
use std::collections::BTreeMap;

/// One piece of a piecewise polynomial surface: `surface` on the cell `rect` = [a, b] x [c, d]
/// of the global parameters (u, v) (power basis of u and v).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(
        deny_unknown_fields,
        bound(
            serialize = "T: crate::Ring + serde::Serialize",
            deserialize = "T: crate::Ring + serde::Deserialize<'de>"
        )
    )
)]
pub struct SurfacePiece<T> {
    /// The cell as `[a, b, c, d]`, a < b and c < d.
    pub rect: [T; 4],
    /// The polynomial on it, of bidegree <= (p, q) (zero coefficients beyond are allowed).
    pub surface: PowerSurface<T>,
}

/// The pieces' coefficient grids checked against (p, q) and padded to (p + 1) x (q + 1).
fn normalise<T: Field>(
    (p, q): (usize, usize),
    pieces: &[SurfacePiece<T>],
) -> Result<Vec<Vec<Vec<Point<T>>>>> {
    let Some(first) = pieces.first() else {
        return Err(Error::of(
            ErrorKind::Empty,
            "pieces",
            "expected at least one piece",
        ));
    };
    let dim = first.surface.dim();
    let (rows, cols) = match (p.checked_add(1), q.checked_add(1)) {
        (Some(r), Some(c)) if r.checked_mul(c).and_then(|n| n.checked_mul(dim)).is_some() => (r, c),
        _ => {
            return Err(Error::of(
                ErrorKind::Degree,
                "degree",
                format!("the bidegree ({p}, {q}) is too large for a coefficient grid"),
            ))
        }
    };
    let mut out = Vec::with_capacity(pieces.len());
    for (k, piece) in pieces.iter().enumerate() {
        let [a, b, c, d] = &piece.rect;
        check_all_finite(&piece.rect, &format!("pieces[{k}].rect"))?;
        if !(a < b && c < d) {
            return Err(Error::of(
                ErrorKind::Domain,
                format!("pieces[{k}].rect"),
                format!("expected a < b and c < d, found [{a}, {b}] x [{c}, {d}]"),
            ));
        }
        if piece.surface.dim() != dim {
            return Err(Error::of(
                ErrorKind::Dimension,
                format!("pieces[{k}].coefficients[0][0]"),
                format!("expected {dim} coordinates, found {}", piece.surface.dim()),
            ));
        }
        let surface = &piece.surface;
        let n = surface.degree().0;
        for (i, row) in surface.rows().enumerate() {
            for (j, x) in row.iter().enumerate() {
                if (i > p || j > q) && x.iter().any(|y| !y.is_zero()) {
                    return Err(Error::of(
                        ErrorKind::Degree,
                        format!("pieces[{k}].coefficients[{i}][{j}]"),
                        format!("the piece has bidegree above (p, q) = ({p}, {q})"),
                    ));
                }
            }
        }
        let padded = (0..rows)
            .map(|i| {
                (0..cols)
                    .map(|j| {
                        (i <= n)
                            .then(|| surface.row(i))
                            .and_then(|row| row.get(j))
                            .map(<[T]>::to_vec)
                            .unwrap_or_else(|| crate::shape::point::zero(dim))
                    })
                    .collect()
            })
            .collect();
        out.push(padded);
    }
    Ok(out)
}

/// The breakpoints of the pieces and the piece on every cell of their grid.
#[derive(Debug)]
struct Grid<T> {
    us: Vec<T>,
    vs: Vec<T>,
    /// `cells[i][j]`: the index of the piece on [u_i, u_{i+1}] x [v_j, v_{j+1}].
    cells: Vec<Vec<usize>>,
}

/// Sorted distinct values; every value is comparable (the rectangles were checked a < b).
fn breakpoints<T: Field>(values: impl Iterator<Item = T>) -> Vec<T> {
    let mut v: Vec<T> = values.collect();
    v.sort_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
    v.dedup();
    v
}

fn index_of<T: Field>(sorted: &[T], x: &T) -> usize {
    sorted
        .binary_search_by(|y| y.partial_cmp(x).unwrap_or(Ordering::Equal))
        .expect("a breakpoint of the grid")
}

/// The grid of the pieces: every piece must be exactly one cell of the grid of all
/// breakpoints, and every cell must have exactly one piece.
fn grid<T: Field>(pieces: &[SurfacePiece<T>]) -> Result<Grid<T>> {
    let us = breakpoints(pieces.iter().flat_map(|s| s.rect[..2].to_vec()));
    let vs = breakpoints(pieces.iter().flat_map(|s| s.rect[2..].to_vec()));
    let mut owner: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for (k, piece) in pieces.iter().enumerate() {
        let [a, b, c, d] = &piece.rect;
        let (i, j) = (index_of(&us, a), index_of(&vs, c));
        let inside = if index_of(&us, b) != i + 1 {
            Some(format!("u = {}", us[i + 1]))
        } else if index_of(&vs, d) != j + 1 {
            Some(format!("v = {}", vs[j + 1]))
        } else {
            None
        };
        if let Some(line) = inside {
            return Err(Error::of(
                ErrorKind::Domain,
                format!("pieces[{k}].rect"),
                format!(
                    "[{a}, {b}] x [{c}, {d}] is not one cell of the grid of breakpoints: \
                     the breakpoint {line} of another piece lies inside it"
                ),
            ));
        }
        if let Some(other) = owner.insert((i, j), k) {
            return Err(Error::of(
                ErrorKind::Domain,
                format!("pieces[{k}].rect"),
                format!("the cell [{a}, {b}] x [{c}, {d}] is also the cell of pieces[{other}]"),
            ));
        }
    }
    let (nu, nv) = (us.len() - 1, vs.len() - 1);
    // The cells are distinct, so there are at most nu * nv of them; fewer leaves a cell empty,
    // found among the first pieces.len() + 1 cells in order.
    if nu.checked_mul(nv) != Some(pieces.len()) {
        let (i, j) = (0..nu)
            .flat_map(|i| (0..nv).map(move |j| (i, j)))
            .find(|c| !owner.contains_key(c))
            .expect("fewer pieces than cells");
        return Err(Error::of(
            ErrorKind::Domain,
            "pieces",
            format!(
                "no piece covers the cell [{}, {}] x [{}, {}] of the grid of breakpoints",
                us[i],
                us[i + 1],
                vs[j],
                vs[j + 1]
            ),
        ));
    }
    let mut cells = vec![vec![0; nv]; nu];
    for ((i, j), k) in owner {
        cells[i][j] = k;
    }
    Ok(Grid { us, vs, cells })
}

/// The knots p + 1 times `breaks[0]`, p - r_i times every interior `breaks[i]` and p + 1 times
/// the last, with r_i the lowest of `continuity(i)` over the lines' cells.
fn knots<T: Field>(p: usize, breaks: &[T], continuity: impl Fn(usize) -> isize) -> Vec<T> {
    let mut knots = vec![breaks[0].clone(); p + 1];
    for (i, e) in breaks.iter().enumerate().take(breaks.len() - 1).skip(1) {
        let mult = (p as isize - continuity(i)) as usize;
        knots.extend(std::iter::repeat_n(e.clone(), mult));
    }
    knots.extend(std::iter::repeat_n(breaks[breaks.len() - 1].clone(), p + 1));
    knots
}

/// The B-spline surface of bidegree `degree` = (p, q) equal to the piecewise polynomial
/// surface `pieces` (one per cell of a grid, in any order), with knot multiplicities from the
/// continuity that holds exactly across each grid line (Theorem 2.4 in u and in v).
///
/// Errors: no pieces (`pieces`); a rectangle with a >= b or c >= d, a piece that is not one
/// cell of the grid of all breakpoints or shares its cell (`pieces[k].rect`); an empty cell
/// (`pieces`); a dimension (`pieces[k].coefficients[0][0]`) or a bidegree above (p, q)
/// (`pieces[k].coefficients[i][j]`). In float arithmetic the continuity is judged on rounded
/// Taylor coefficients, which rounding can make unequal: use exact numbers.
///
/// ```
/// use blossom::{bspline_surface_from_pieces, PowerSurface, Rational, SurfacePiece};
/// let q = |n: i64| Rational::from_integer(n.into());
/// // u^2 v on [0, 1] x [0, 1] and (2u - 1) v on [1, 2] x [0, 1]: C^1 across u = 1.
/// let piece = |a, b, c: Vec<Vec<i64>>| SurfacePiece {
///     rect: [q(a), q(b), q(0), q(1)],
///     surface: PowerSurface::new(c.iter().map(|r| r.iter().map(|&x| vec![q(x)]).collect()).collect()).unwrap(),
/// };
/// let f = bspline_surface_from_pieces((2, 1), &[
///     piece(0, 1, vec![vec![0, 0], vec![0, 0], vec![0, 1]]),
///     piece(1, 2, vec![vec![0, -1], vec![0, 2]]),
/// ])?;
/// assert_eq!(f.u_knots(), &[0, 0, 0, 1, 2, 2, 2].map(q));
/// assert_eq!(f.v_knots(), &[0, 0, 1, 1].map(q));
/// assert_eq!(f.row(2), vec![vec![q(0)], vec![q(2)]]);
/// # Ok::<(), blossom::Error>(())
/// ```
pub fn bspline_surface_from_pieces<T: Field>(
    degree: (usize, usize),
    pieces: &[SurfacePiece<T>],
) -> Result<BSplineSurface<T>> {
    let (p, q) = degree;
    let grids = normalise(degree, pieces)?;
    let g = grid(pieces)?;
    // Each piece as a curve in u of long points (its rows: polynomials in v) and as a curve in
    // v of long points (its columns: polynomials in u).
    let in_u: Vec<PowerCurve<T>> = grids
        .iter()
        .map(|c| PowerCurve::new(flatten(c)).expect("p + 1 long points"))
        .collect();
    let in_v: Vec<PowerCurve<T>> = grids
        .iter()
        .map(|c| {
            let columns: Vec<Vec<Point<T>>> = (0..=q)
                .map(|j| c.iter().map(|row| row[j].clone()).collect())
                .collect();
            PowerCurve::new(flatten(&columns)).expect("q + 1 long points")
        })
        .collect();
    let cells = &g.cells;
    let u_knots = knots(p, &g.us, |i| {
        (0..g.vs.len() - 1)
            .map(|j| continuity_at(&in_u[cells[i - 1][j]], &in_u[cells[i][j]], &g.us[i]))
            .min()
            .expect("at least one row of cells")
    });
    let v_knots = knots(q, &g.vs, |j| {
        (0..g.us.len() - 1)
            .map(|i| continuity_at(&in_v[cells[i][j - 1]], &in_v[cells[i][j]], &g.vs[j]))
            .min()
            .expect("at least one column of cells")
    });
    let kv_u = super::knots::KnotVector::new(p, u_knots)?;
    let kv_v = super::knots::KnotVector::new(q, v_knots)?;
    let (t, s) = (kv_u.knots(), kv_v.knots());
    let (m, n) = (kv_u.control_count(), kv_v.control_count());
    let mut points: Vec<Vec<Option<Point<T>>>> = vec![vec![None; n]; m];
    for sigma in kv_u.spans() {
        let i = index_of(&g.us, &t[sigma]);
        for tau in kv_v.spans() {
            let surface = PowerSurface::new(grids[cells[i][index_of(&g.vs, &s[tau])]].clone())
                .expect("a padded grid");
            for (k, row) in points
                .iter_mut()
                .enumerate()
                .take(sigma + 1)
                .skip(sigma - p)
            {
                for (l, d) in row.iter_mut().enumerate().take(tau + 1).skip(tau - q) {
                    if d.is_none() {
                        *d = Some(tensor_blossom(
                            &surface,
                            &t[k + 1..=k + p],
                            &s[l + 1..=l + q],
                        )?);
                    }
                }
            }
        }
    }
    let dim = pieces[0].surface.dim();
    let mut coords = Vec::with_capacity(m * n * dim);
    for d in points.into_iter().flatten() {
        coords.extend(d.expect("every de Boor point acts on a span of the domain"));
    }
    BSplineSurface::from_grid(degree, t.to_vec(), s.to_vec(), (m, n), dim, coords)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rational;
    use num_bigint::BigInt;

    fn q(n: i64) -> Rational {
        Rational::from_integer(BigInt::from(n))
    }

    fn piece(rect: [i64; 4], c: i64) -> SurfacePiece<Rational> {
        SurfacePiece {
            rect: rect.map(q),
            surface: PowerSurface::new(vec![vec![vec![q(c)]]]).unwrap(),
        }
    }

    #[test]
    fn grids_are_checked() {
        let ok = [
            piece([1, 2, 0, 1], 0),
            piece([0, 1, 0, 1], 0),
            piece([0, 1, 1, 3], 0),
            piece([1, 2, 1, 3], 0),
        ];
        let g = grid(&ok).unwrap();
        assert_eq!(g.cells, vec![vec![1, 2], vec![0, 3]]);
        // A T-junction: [0, 2] x [1, 3] spans the breakpoint u = 1.
        let t = [
            piece([1, 2, 0, 1], 0),
            piece([0, 1, 0, 1], 0),
            piece([0, 2, 1, 3], 0),
        ];
        let e = grid(&t).unwrap_err();
        assert_eq!(
            (e.kind, e.field.as_str()),
            (ErrorKind::Domain, "pieces[2].rect")
        );
        let missing = [piece([0, 1, 0, 1], 0), piece([1, 2, 1, 2], 0)];
        let e = grid(&missing).unwrap_err();
        assert_eq!(e.field, "pieces");
        assert!(e.message.contains("[0, 1] x [1, 2]"), "{e}");
        let twice = [piece([0, 1, 0, 1], 0), piece([0, 1, 0, 1], 1)];
        assert!(grid(&twice).unwrap_err().message.contains("pieces[0]"));
    }
}
