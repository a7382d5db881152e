//! Tensor-product B-spline and NURBS surfaces, cross-checked between independent algorithms:
//! the knot multiplicities against continuities built into the pieces by construction, de
//! Boor's algorithm against the pieces' power form (Horner) and against the recursive
//! definition of the N_i^p (Cox-de Boor), the blossom against the inverse formula (samples of
//! the piece only), the Bézier patches against the restriction engine's closed form (9), knot
//! insertion against the surface before it; the rational form against N / w by Horner and
//! against eq. (22) on the homogeneous pieces.

use super::json::Json;
use crate::common::{q, Rng};
use blossom::engine::bspline_basis_on_span;
use blossom::{
    bezier_tensor_blossom, bspline_surface_from_pieces, restrict_power_surface,
    tensor_blossom_from_samples, BSplineSurface, BezierCell, ErrorKind, KnotVector, Method,
    PowerSurface, Rational, RationalBSplineSurface, RationalSurface, Ring, SurfacePiece,
    TensorPatch,
};

type Grid = Vec<Vec<Vec<Rational>>>;

/// (a0 + a1 x + ...) (b0 + b1 x + ...).
fn poly_mul(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut out = vec![q(0, 1); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = &out[i + j] + x * y;
        }
    }
    out
}

/// (x - r)^e (x - s)^f in the power basis.
fn two_roots(r: &Rational, e: usize, s: &Rational, f: usize) -> Vec<Rational> {
    let mut out = vec![q(1, 1)];
    for _ in 0..e {
        out = poly_mul(&out, &[-r.clone(), q(1, 1)]);
    }
    for _ in 0..f {
        out = poly_mul(&out, &[-s.clone(), q(1, 1)]);
    }
    out
}

/// The coefficient grid padded with zeros to (p + 1) x (q + 1).
fn padded(c: &[Vec<Vec<Rational>>], p: usize, qd: usize, dim: usize) -> PowerSurface<Rational> {
    PowerSurface::new(
        (0..=p)
            .map(|i| {
                (0..=qd)
                    .map(|j| {
                        c.get(i)
                            .and_then(|r| r.get(j))
                            .cloned()
                            .unwrap_or_else(|| vec![q(0, 1); dim])
                    })
                    .collect()
            })
            .collect(),
    )
    .unwrap()
}

/// A piecewise polynomial surface with known continuities: one global polynomial on every
/// cell, plus, on some cells (i + j even, so no two share an edge), the perturbation
/// delta (u - u_i)^a (u - u_{i+1})^b (v - v_j)^c (v - v_{j+1})^e. Across u = u_i the jump in
/// that row of cells is delta (u_i - u_{i+1})^b (...)(v) (u - u_i)^a + ..., so the exact order
/// of continuity there is a - 1; across a line the surface's order is the lowest over its
/// cells (p or q where nothing was perturbed).
struct Case {
    p: usize,
    qd: usize,
    dim: usize,
    us: Vec<Rational>,
    vs: Vec<Rational>,
    pieces: Vec<SurfacePiece<Rational>>,
    /// `cell[i][j]`: the index in `pieces` of the piece on cell (i, j).
    cell: Vec<Vec<usize>>,
    u_cont: Vec<isize>,
    v_cont: Vec<isize>,
}

fn breaks(rng: &mut Rng, start: Rational, count: usize) -> Vec<Rational> {
    let mut v = vec![start];
    for _ in 0..count {
        let step = q((rng.next() % 3) as i64 + 1, (rng.next() % 2) as i64 + 1);
        let next = v.last().unwrap() + step;
        v.push(next);
    }
    v
}

fn nonzero_point(rng: &mut Rng, dim: usize) -> Vec<Rational> {
    loop {
        let p = rng.point(dim);
        if p.iter().any(|x| !x.is_zero()) {
            return p;
        }
    }
}

/// `random_case_from` with breakpoints from a random start.
fn random_case(
    rng: &mut Rng,
    deg: (usize, usize),
    cells: (usize, usize),
    dim: usize,
    perturb: bool,
) -> Case {
    let start = rng.rational() / q(4, 1);
    random_case_from(rng, start, deg, cells, dim, perturb)
}

fn random_case_from(
    rng: &mut Rng,
    start: Rational,
    (p, qd): (usize, usize),
    (nu, nv): (usize, usize),
    dim: usize,
    perturb: bool,
) -> Case {
    let us = breaks(rng, start.clone(), nu);
    let vs = breaks(rng, start, nv);
    // The global polynomial, sometimes of a lower bidegree.
    let low = |d: usize, r: u64| {
        if d > 0 && r.is_multiple_of(3) {
            d - 1
        } else {
            d
        }
    };
    let (bp, bq) = (low(p, rng.next()), low(qd, rng.next()));
    let base = padded(&rng.surface(bp, bq, dim).to_nested(), p, qd, dim);
    let mut u_cont = vec![p as isize; nu.saturating_sub(1)];
    let mut v_cont = vec![qd as isize; nv.saturating_sub(1)];
    let mut grids = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let mut c: Grid = base.to_nested();
            if perturb && (i + j) % 2 == 0 && !rng.next().is_multiple_of(3) {
                let a = (rng.next() % (p as u64 + 1)) as usize;
                let b = (rng.next() % ((p - a) as u64 + 1)) as usize;
                let cc = (rng.next() % (qd as u64 + 1)) as usize;
                let e = (rng.next() % ((qd - cc) as u64 + 1)) as usize;
                let pu = two_roots(&us[i], a, &us[i + 1], b);
                let pv = two_roots(&vs[j], cc, &vs[j + 1], e);
                let delta = nonzero_point(rng, dim);
                for (x, cu) in pu.iter().enumerate() {
                    for (y, cv) in pv.iter().enumerate() {
                        let k = cu * cv;
                        for (z, d) in c[x][y].iter_mut().zip(&delta) {
                            *z = &*z + &k * d;
                        }
                    }
                }
                // Line u_i is line index i (interior when 1 <= i < nu), u_{i+1} is i + 1.
                if i >= 1 {
                    u_cont[i - 1] = u_cont[i - 1].min(a as isize - 1);
                }
                if i + 1 < nu {
                    u_cont[i] = u_cont[i].min(b as isize - 1);
                }
                if j >= 1 {
                    v_cont[j - 1] = v_cont[j - 1].min(cc as isize - 1);
                }
                if j + 1 < nv {
                    v_cont[j] = v_cont[j].min(e as isize - 1);
                }
            }
            // Trailing zero rows and columns dropped: pieces of a bidegree below (p, q).
            while c.len() > 1 && c.last().unwrap().iter().flatten().all(Ring::is_zero) {
                c.pop();
            }
            while c[0].len() > 1
                && c.iter()
                    .all(|r| r.last().unwrap().iter().all(Ring::is_zero))
            {
                for r in c.iter_mut() {
                    r.pop();
                }
            }
            grids.push(((i, j), c));
        }
    }
    // The pieces in a shuffled order (Fisher-Yates): the grid is found from the rectangles.
    for k in (1..grids.len()).rev() {
        let r = (rng.next() % (k as u64 + 1)) as usize;
        grids.swap(k, r);
    }
    let mut cell = vec![vec![0; nv]; nu];
    let pieces = grids
        .into_iter()
        .enumerate()
        .map(|(k, ((i, j), c))| {
            cell[i][j] = k;
            SurfacePiece {
                rect: [
                    us[i].clone(),
                    us[i + 1].clone(),
                    vs[j].clone(),
                    vs[j + 1].clone(),
                ],
                surface: PowerSurface::new(c).unwrap(),
            }
        })
        .collect();
    Case {
        p,
        qd,
        dim,
        us,
        vs,
        pieces,
        cell,
        u_cont,
        v_cont,
    }
}

/// The cell index i with breaks[i] <= x < breaks[i + 1] (the last cell at the right end).
fn cell_of(breaks: &[Rational], x: &Rational) -> usize {
    (0..breaks.len() - 1)
        .rev()
        .find(|&i| breaks[i] <= *x)
        .unwrap()
}

impl Case {
    fn piece_at(&self, u: &Rational, v: &Rational) -> &SurfacePiece<Rational> {
        &self.pieces[self.cell[cell_of(&self.us, u)][cell_of(&self.vs, v)]]
    }

    fn expected_knots(&self, breaks: &[Rational], deg: usize, cont: &[isize]) -> Vec<Rational> {
        let mut k = vec![breaks[0].clone(); deg + 1];
        for (e, r) in breaks[1..breaks.len() - 1].iter().zip(cont) {
            k.extend(std::iter::repeat_n(e.clone(), (deg as isize - r) as usize));
        }
        k.extend(std::iter::repeat_n(breaks.last().unwrap().clone(), deg + 1));
        k
    }

    /// Points of the domain: a few per cell, on its lower and left edges too, and the corners.
    fn sample_points(&self, rng: &mut Rng) -> Vec<(Rational, Rational)> {
        let mut out = Vec::new();
        for i in 0..self.us.len() - 1 {
            for j in 0..self.vs.len() - 1 {
                let du = &self.us[i + 1] - &self.us[i];
                let dv = &self.vs[j + 1] - &self.vs[j];
                for _ in 0..4 {
                    let s = q((rng.next() % 97) as i64, 97);
                    let t = q((rng.next() % 89) as i64, 89);
                    out.push((&self.us[i] + &du * &s, &self.vs[j] + &dv * &t));
                }
                out.push((self.us[i].clone(), self.vs[j].clone()));
            }
        }
        let (a, b) = (self.us[0].clone(), self.us.last().unwrap().clone());
        let (c, d) = (self.vs[0].clone(), self.vs.last().unwrap().clone());
        out.extend([(b.clone(), d.clone()), (a, d), (b, c)]);
        out
    }

    /// Every Bézier cell of `f` equals the engine's closed form (9) of its piece on the cell.
    fn check_bezier(&self, f: &BSplineSurface<Rational>, label: &str) {
        let cells = f.bezier_patches();
        let distinct = |k: &[Rational]| {
            let mut v = k.to_vec();
            v.dedup();
            v
        };
        let (du, dv) = (distinct(f.u_knots()), distinct(f.v_knots()));
        assert_eq!(cells.len(), (du.len() - 1) * (dv.len() - 1), "{label}");
        let mut k = 0;
        for i in 0..du.len() - 1 {
            for j in 0..dv.len() - 1 {
                let rect = [
                    du[i].clone(),
                    du[i + 1].clone(),
                    dv[j].clone(),
                    dv[j + 1].clone(),
                ];
                let cell = &cells[k];
                k += 1;
                assert_eq!(cell.rect, rect, "{label}");
                let piece = self.piece_at(&rect[0], &rect[2]);
                let src = padded(&piece.surface.to_nested(), self.p, self.qd, self.dim);
                let want = restrict_power_surface(&src, &rect, Method::ClosedForm);
                assert_eq!(cell.patch, want, "{label} cell {rect:?}");
            }
        }
    }

    fn check_values(&self, f: &BSplineSurface<Rational>, rng: &mut Rng, label: &str) {
        for (u, v) in self.sample_points(rng) {
            assert_eq!(
                f.eval(&u, &v).unwrap(),
                self.piece_at(&u, &v).surface.eval(&u, &v),
                "{label} at ({u}, {v})"
            );
        }
    }
}

const DEGREES: [(usize, usize); 7] = [(0, 0), (0, 2), (1, 1), (2, 1), (1, 3), (3, 2), (2, 3)];

#[test]
fn multiplicities_are_the_exact_continuity_across_each_line() {
    let mut rng = Rng(70);
    let mut seen_drop = 0;
    for deg in DEGREES {
        for cells in [(1, 1), (2, 3), (3, 2), (3, 3)] {
            for perturb in [false, true, true] {
                let case = random_case(&mut rng, deg, cells, 2, perturb);
                let f = bspline_surface_from_pieces(deg, &case.pieces).unwrap();
                let label = format!("deg {deg:?} cells {cells:?} perturb {perturb}");
                assert_eq!(
                    f.u_knots(),
                    case.expected_knots(&case.us, deg.0, &case.u_cont)
                        .as_slice(),
                    "{label} u continuities {:?}",
                    case.u_cont
                );
                assert_eq!(
                    f.v_knots(),
                    case.expected_knots(&case.vs, deg.1, &case.v_cont)
                        .as_slice(),
                    "{label} v continuities {:?}",
                    case.v_cont
                );
                if !perturb {
                    // One global polynomial: every interior line disappears.
                    assert_eq!(f.u_knots().len(), 2 * deg.0 + 2, "{label}");
                    assert_eq!(f.v_knots().len(), 2 * deg.1 + 2, "{label}");
                }
                seen_drop += case
                    .u_cont
                    .iter()
                    .chain(&case.v_cont)
                    .filter(|&&r| r < 0)
                    .count();
            }
        }
    }
    // Discontinuous lines (multiplicity p + 1) occurred among the cases.
    assert!(seen_drop > 5, "{seen_drop}");
}

#[test]
fn de_boor_evaluation_and_bezier_patches_equal_the_pieces() {
    let mut rng = Rng(71);
    for deg in DEGREES {
        for cells in [(1, 2), (3, 2), (2, 3)] {
            let case = random_case(&mut rng, deg, cells, 3, true);
            let f = bspline_surface_from_pieces(deg, &case.pieces).unwrap();
            let label = format!("deg {deg:?} cells {cells:?}");
            case.check_values(&f, &mut rng, &label);
            case.check_bezier(&f, &label);
        }
    }
}

#[test]
fn blossom_on_a_cell_is_the_inverse_formula_of_its_piece() {
    let mut rng = Rng(72);
    for deg in DEGREES {
        let case = random_case(&mut rng, deg, (2, 2), 2, true);
        let f = bspline_surface_from_pieces(deg, &case.pieces).unwrap();
        let (t, s) = (f.u_knots().to_vec(), f.v_knots().to_vec());
        for sigma in f.u_knot_vector().spans() {
            for tau in f.v_knot_vector().spans() {
                let piece = case.piece_at(&t[sigma], &s[tau]);
                let us: Vec<Rational> = (0..deg.0).map(|_| rng.rational()).collect();
                let vs: Vec<Rational> = (0..deg.1).map(|_| rng.rational()).collect();
                let want =
                    tensor_blossom_from_samples(deg, &us, &vs, &|u, v| piece.surface.eval(u, v))
                        .unwrap();
                assert_eq!(f.blossom((sigma, tau), &us, &vs).unwrap(), want, "{deg:?}");
                // Symmetric in each group of arguments.
                let (ru, rv): (Vec<_>, Vec<_>) = (
                    us.iter().rev().cloned().collect(),
                    vs.iter().rev().cloned().collect(),
                );
                assert_eq!(f.blossom((sigma, tau), &ru, &rv).unwrap(), want);
            }
        }
    }
}

/// A random knot vector of degree p with `extra` interior knots (random multiplicities).
fn random_knots(rng: &mut Rng, p: usize, extra: usize) -> Vec<Rational> {
    loop {
        let mut k = vec![rng.rational() / q(5, 1)];
        for _ in 1..2 * p + 2 + extra {
            let step = q((rng.next() % 4) as i64, 2);
            let next = k.last().unwrap() + step;
            k.push(next);
        }
        if KnotVector::new(p, k.clone()).is_ok() {
            return k;
        }
    }
}

/// sum_e c_e x^e.
fn horner(c: &[Rational], x: &Rational) -> Rational {
    c.iter().rev().fold(q(0, 1), |acc, ci| acc * x + ci)
}

#[test]
fn de_boor_equals_the_cox_de_boor_basis_on_random_surfaces() {
    let mut rng = Rng(73);
    for deg in DEGREES {
        for _ in 0..2 {
            let (p, qd) = deg;
            let (eu, ev) = ((rng.next() % 3) as usize, (rng.next() % 3) as usize);
            let tu = random_knots(&mut rng, p, eu);
            let tv = random_knots(&mut rng, qd, ev);
            let (m, n) = (tu.len() - p - 1, tv.len() - qd - 1);
            let grid: Grid = (0..m)
                .map(|_| (0..n).map(|_| rng.point(2)).collect())
                .collect();
            let f = BSplineSurface::new(deg, tu.clone(), tv.clone(), grid.clone()).unwrap();
            let [a, b, c, d] = f.domain().map(Clone::clone);
            for k in 0..12 {
                let u = if k == 0 {
                    b.clone()
                } else {
                    &a + (&b - &a) * q((rng.next() % 61) as i64, 60)
                };
                let v = if k == 1 {
                    d.clone()
                } else {
                    &c + (&d - &c) * q((rng.next() % 61) as i64, 60)
                };
                let (su, sv) = f.span(&u, &v).unwrap();
                let nu = bspline_basis_on_span(&tu, p, su).unwrap();
                let nv = bspline_basis_on_span(&tv, qd, sv).unwrap();
                let mut want = vec![q(0, 1); 2];
                for (i, bu) in nu.iter().enumerate() {
                    for (j, bv) in nv.iter().enumerate() {
                        let w = horner(bu, &u) * horner(bv, &v);
                        for (x, y) in want.iter_mut().zip(&grid[su - p + i][sv - qd + j]) {
                            *x = &*x + &w * y;
                        }
                    }
                }
                assert_eq!(f.eval(&u, &v).unwrap(), want, "{deg:?} at ({u}, {v})");
                // The piece on the cell in the power basis, from the basis polynomials; its
                // inverse-formula blossom is the surface's blossom on the cell.
                let coeffs: Grid = (0..=p)
                    .map(|e| {
                        (0..=qd)
                            .map(|g| {
                                let mut acc = vec![q(0, 1); 2];
                                for (i, bu) in nu.iter().enumerate() {
                                    for (j, bv) in nv.iter().enumerate() {
                                        let w = &bu[e] * &bv[g];
                                        for (x, y) in
                                            acc.iter_mut().zip(&grid[su - p + i][sv - qd + j])
                                        {
                                            *x = &*x + &w * y;
                                        }
                                    }
                                }
                                acc
                            })
                            .collect()
                    })
                    .collect();
                let piece = PowerSurface::new(coeffs).unwrap();
                let us: Vec<Rational> = (0..p).map(|_| rng.rational()).collect();
                let vs: Vec<Rational> = (0..qd).map(|_| rng.rational()).collect();
                let want =
                    tensor_blossom_from_samples(deg, &us, &vs, &|x, y| piece.eval(x, y)).unwrap();
                assert_eq!(f.blossom((su, sv), &us, &vs).unwrap(), want, "{deg:?}");
            }
        }
    }
}

#[test]
fn knot_insertion_keeps_values_and_bezier_patches() {
    let mut rng = Rng(74);
    for deg in DEGREES {
        let (p, qd) = deg;
        let case = random_case(&mut rng, deg, (3, 2), 2, true);
        let f = bspline_surface_from_pieces(deg, &case.pieces).unwrap();
        let label = format!("deg {deg:?}");
        let interior = |k: &[Rational], deg: usize| {
            let mut v = k[deg + 1..k.len() - deg - 1].to_vec();
            v.dedup();
            v
        };
        // At an existing knot below full multiplicity: the same cells, the same patches.
        for x in interior(f.u_knots(), p) {
            match f.insert_u_knot(&x) {
                Ok(g) => {
                    assert_eq!(g.bezier_patches(), f.bezier_patches(), "{label} u = {x}");
                    case.check_values(&g, &mut rng, &label);
                }
                Err(e) => {
                    assert_eq!(f.u_knot_vector().multiplicity(&x), p + 1, "{e}");
                    assert_eq!(e.kind, ErrorKind::Domain);
                    assert!(e.field.starts_with("u_knots["), "{e}");
                }
            }
        }
        for x in interior(f.v_knots(), qd) {
            if let Ok(g) = f.insert_v_knot(&x) {
                assert_eq!(g.bezier_patches(), f.bezier_patches(), "{label} v = {x}");
            }
        }
        // At new knots: the surface and the patches of the untouched cells are unchanged, and
        // the split cells are the pieces' restrictions.
        let [a, b, c, d] = f.domain().map(Clone::clone);
        let xu = &a + (&b - &a) * q(37, 101);
        let xv = &c + (&d - &c) * q(64, 103);
        let g = f.insert_u_knot(&xu).unwrap().insert_v_knot(&xv).unwrap();
        assert_eq!(g.control_points().len(), f.control_points().len() + 1);
        assert_eq!(g.row(0).len(), f.row(0).len() + 1);
        case.check_values(&g, &mut rng, &label);
        case.check_bezier(&g, &label);
        let new: Vec<BezierCell<Rational>> = g.bezier_patches();
        for old in f.bezier_patches() {
            let [ca, cb, cc, cd] = &old.rect;
            let split = (*ca < xu && xu < *cb) || (*cc < xv && xv < *cd);
            assert_eq!(new.contains(&old), !split, "{label} {:?}", old.rect);
        }
        // Raising every interior multiplicity to p in u and q in v (Boehm's route): the de Boor
        // points of each cell are then its Bézier net.
        let mut h = f.clone();
        for x in interior(f.u_knots(), p) {
            while h.u_knot_vector().multiplicity(&x) < p {
                h = h.insert_u_knot(&x).unwrap();
            }
        }
        for x in interior(f.v_knots(), qd) {
            while h.v_knot_vector().multiplicity(&x) < qd {
                h = h.insert_v_knot(&x).unwrap();
            }
        }
        let cells = f.bezier_patches();
        let mut k = 0;
        for s in h.u_knot_vector().spans() {
            for t in h.v_knot_vector().spans() {
                let block: Grid = (s - p..=s)
                    .map(|k| h.row(k).slice(t - qd..t + 1).to_vec())
                    .collect();
                assert_eq!(block, cells[k].patch.to_nested(), "{label} cell {k}");
                k += 1;
            }
        }
        assert_eq!(k, cells.len());
    }
}

#[test]
fn a_single_span_surface_is_its_bezier_patch() {
    let mut rng = Rng(75);
    for deg in DEGREES {
        let (p, qd) = deg;
        let (a, c) = (rng.rational(), rng.rational());
        let (b, d) = (
            &a + q((rng.next() % 5) as i64 + 1, 2),
            &c + q((rng.next() % 5) as i64 + 1, 3),
        );
        let net: Grid = (0..=p)
            .map(|_| (0..=qd).map(|_| rng.point(3)).collect())
            .collect();
        let clamp = |x: &Rational, y: &Rational, k: usize| {
            let mut v = vec![x.clone(); k + 1];
            v.extend(vec![y.clone(); k + 1]);
            v
        };
        let f = BSplineSurface::new(deg, clamp(&a, &b, p), clamp(&c, &d, qd), net.clone()).unwrap();
        let patch = TensorPatch::new(net.clone()).unwrap();
        let rect = [a.clone(), b.clone(), c.clone(), d.clone()];
        assert_eq!(
            f.bezier_patches(),
            vec![BezierCell {
                rect,
                patch: patch.clone()
            }]
        );
        for _ in 0..10 {
            let (s, t) = (
                q((rng.next() % 50) as i64, 49),
                q((rng.next() % 50) as i64, 49),
            );
            let (u, v) = (&a + (&b - &a) * &s, &c + (&d - &c) * &t);
            assert_eq!(f.eval(&u, &v).unwrap(), patch.eval(&s, &t), "{deg:?}");
            // The blossom at global arguments is the patch's blossom at the local ones.
            let us: Vec<Rational> = (0..p).map(|_| rng.rational()).collect();
            let vs: Vec<Rational> = (0..qd).map(|_| rng.rational()).collect();
            let local_u: Vec<Rational> = us.iter().map(|x| (x - &a) / (&b - &a)).collect();
            let local_v: Vec<Rational> = vs.iter().map(|x| (x - &c) / (&d - &c)).collect();
            assert_eq!(
                f.blossom((p, qd), &us, &vs).unwrap(),
                bezier_tensor_blossom(&net, &local_u, &local_v).unwrap()
            );
        }
    }
}

/// Pieces of a rational surface N / w on breakpoints from 0: the numerator from
/// `random_case_from`, the denominator one polynomial with a positive constant and
/// non-negative coefficients on every cell (so every blossom value of w at the non-negative
/// knots is positive).
fn rational_case(
    rng: &mut Rng,
    deg: (usize, usize),
    cells: (usize, usize),
) -> (Case, Vec<RationalSurface<Rational>>) {
    let mut case = random_case_from(rng, q(0, 1), deg, cells, 2, true);
    let den: Vec<Vec<Rational>> = (0..=deg.0)
        .map(|i| {
            (0..=deg.1)
                .map(|j| {
                    if i + j == 0 {
                        q(3, 1)
                    } else {
                        q((rng.next() % 3) as i64, (rng.next() % 4) as i64 + 1)
                    }
                })
                .collect()
        })
        .collect();
    let mut rational = Vec::new();
    for piece in case.pieces.iter_mut() {
        let num = padded(&piece.surface.to_nested(), deg.0, deg.1, 2);
        let r = RationalSurface::new(&num.to_nested(), &den).unwrap();
        piece.surface = r.homogeneous().clone();
        rational.push(r);
    }
    case.dim = 3;
    (case, rational)
}

#[test]
fn nurbs_surfaces_from_pieces_are_numerator_over_denominator() {
    let mut rng = Rng(76);
    for deg in DEGREES {
        let (case, rational) = rational_case(&mut rng, deg, (2, 2));
        let h = bspline_surface_from_pieces(deg, &case.pieces).unwrap();
        let f = RationalBSplineSurface::from_homogeneous(h).unwrap();
        assert!(f.weights().iter().flatten().all(|w| *w > q(0, 1)));
        let rat_at = |u: &Rational, v: &Rational| {
            &rational[case.cell[cell_of(&case.us, u)][cell_of(&case.vs, v)]]
        };
        for (u, v) in case.sample_points(&mut rng) {
            assert_eq!(
                f.eval(&u, &v).unwrap(),
                rat_at(&u, &v).eval(&u, &v).unwrap(),
                "{deg:?} at ({u}, {v})"
            );
        }
        // The rational Bézier patches against eq. (22) on the homogeneous piece.
        for cell in f.bezier_patches().unwrap() {
            let want = rat_at(&cell.rect[0], &cell.rect[2])
                .tensor(&cell.rect, Some(deg))
                .unwrap();
            assert_eq!(cell.patch, want, "{deg:?} {:?}", cell.rect);
        }
        // Insertion keeps the surface; the round trip through points and weights is exact.
        let [a, b, c, d] = f.homogeneous().domain().map(Clone::clone);
        let g = f
            .insert_u_knot(&(&a + (&b - &a) * q(2, 7)))
            .unwrap()
            .insert_v_knot(&(&c + (&d - &c) * q(5, 9)))
            .unwrap();
        for (u, v) in case.sample_points(&mut rng) {
            assert_eq!(g.eval(&u, &v).unwrap(), f.eval(&u, &v).unwrap());
        }
        let h = f.homogeneous();
        let again = RationalBSplineSurface::new(
            deg,
            h.u_knots().to_vec(),
            h.v_knots().to_vec(),
            f.points(),
            f.weights(),
        )
        .unwrap();
        assert_eq!(again, f);
    }
}

fn ints(v: &[i64]) -> Vec<Rational> {
    v.iter().map(|&k| q(k, 1)).collect()
}

fn scalar_grid(rows: &[&[i64]]) -> Grid {
    rows.iter()
        .map(|r| r.iter().map(|&x| vec![q(x, 1)]).collect())
        .collect()
}

fn kind_and_field<T: std::fmt::Debug>(r: Result<T, blossom::Error>) -> (ErrorKind, String) {
    let e = r.unwrap_err();
    (e.kind, e.field)
}

#[test]
fn bad_surfaces_are_refused_with_kind_and_field() {
    use ErrorKind::*;
    let k = |v: &[i64]| ints(v);
    let g = scalar_grid(&[&[0, 1], &[2, 3], &[4, 5]]);
    let new = |deg, u: &[i64], v: &[i64], grid: Grid| BSplineSurface::new(deg, k(u), k(v), grid);
    let f = new((1, 1), &[0, 0, 1, 2, 2], &[0, 0, 1, 1], g.clone()).unwrap();
    type Expect = (
        (ErrorKind, &'static str),
        Result<BSplineSurface<Rational>, blossom::Error>,
    );
    let cases: Vec<Expect> = vec![
        (
            (Shape, "u_knots"),
            new((1, 1), &[0, 0, 1, 1], &[0, 0, 1, 1], g.clone()),
        ),
        (
            (Shape, "v_knots"),
            new((1, 1), &[0, 0, 1, 2, 2], &[0, 0, 1, 1, 1], g.clone()),
        ),
        (
            (Shape, "control_points"),
            new((3, 1), &[0; 7], &[0, 0, 1, 1], g.clone()),
        ),
        (
            (Shape, "control_points[0]"),
            new((1, 2), &[0, 0, 1, 2, 2], &[0, 0, 0, 1, 1], g.clone()),
        ),
        (
            (Domain, "u_knots[2]"),
            new((1, 1), &[0, 2, 1, 2, 2], &[0, 0, 1, 1], g.clone()),
        ),
        (
            (Domain, "v_knots[3]"),
            new((1, 1), &[0, 0, 1, 2, 2], &[0, 1, 1, 0], g.clone()),
        ),
        (
            (Domain, "u_knots[3]"),
            new((1, 1), &[0, 1, 1, 1, 2], &[0, 0, 1, 1], g.clone()),
        ),
        (
            (Domain, "v_knots"),
            new((1, 1), &[0, 0, 1, 2, 2], &[0, 1, 1, 2], g.clone()),
        ),
        (
            (Shape, "control_points[1]"),
            new(
                (1, 1),
                &[0, 0, 1, 2, 2],
                &[0, 0, 1, 1],
                scalar_grid(&[&[0, 1], &[2], &[4, 5]]),
            ),
        ),
        (
            (Dimension, "control_points[2][1]"),
            new((1, 1), &[0, 0, 1, 2, 2], &[0, 0, 1, 1], {
                let mut h = g.clone();
                h[2][1] = vec![q(1, 1), q(2, 1)];
                h
            }),
        ),
        (
            (Empty, "control_points"),
            new((1, 1), &[0, 0, 1, 2, 2], &[0, 0, 1, 1], vec![]),
        ),
    ];
    for (want, got) in cases {
        let (kind, field) = kind_and_field(got);
        assert_eq!((kind, field.as_str()), want);
    }
    // Parameters outside the domain, blossoms off a span or with the wrong arity, insertion.
    assert_eq!(
        kind_and_field(f.eval(&q(-1, 2), &q(0, 1))),
        (Domain, "u".into())
    );
    assert_eq!(
        kind_and_field(f.eval(&q(1, 1), &q(3, 2))),
        (Domain, "v".into())
    );
    let one = [q(1, 2)];
    assert_eq!(
        kind_and_field(f.blossom((0, 1), &one, &one)),
        (Domain, "span[0]".into())
    );
    assert_eq!(
        kind_and_field(f.blossom((1, 2), &one, &one)),
        (Domain, "span[1]".into())
    );
    assert_eq!(
        kind_and_field(f.blossom((1, 1), &[], &one)),
        (Arity, "us".into())
    );
    assert_eq!(
        kind_and_field(f.blossom((2, 1), &one, &[q(0, 1), q(1, 1)])),
        (Arity, "vs".into())
    );
    assert_eq!(
        kind_and_field(f.insert_u_knot(&q(5, 2))),
        (Domain, "x".into())
    );
    assert_eq!(
        kind_and_field(f.insert_v_knot(&q(-1, 1))),
        (Domain, "x".into())
    );
    assert_eq!(
        kind_and_field(f.insert_v_knot(&q(0, 1))),
        (Domain, "v_knots[2]".into())
    );
    let twice = f.insert_u_knot(&q(1, 1)).unwrap();
    assert_eq!(
        kind_and_field(twice.insert_u_knot(&q(1, 1))),
        (Domain, "u_knots[4]".into())
    );
}

#[test]
fn bad_pieces_are_refused_with_kind_and_field() {
    use ErrorKind::*;
    let sq = |c: &[&[i64]]| PowerSurface::new(scalar_grid(c)).unwrap();
    let piece = |r: [i64; 4], c: &[&[i64]]| SurfacePiece {
        rect: r.map(|x| q(x, 1)),
        surface: sq(c),
    };
    let ok = |r: [i64; 4]| piece(r, &[&[1, 1], &[1, 0]]);
    let run = |pieces: Vec<SurfacePiece<Rational>>| {
        kind_and_field(bspline_surface_from_pieces((1, 1), &pieces))
    };
    assert_eq!(run(vec![]), (Empty, "pieces".into()));
    assert_eq!(
        run(vec![ok([0, 1, 0, 1]), ok([1, 1, 0, 1])]),
        (Domain, "pieces[1].rect".into())
    );
    assert_eq!(
        run(vec![ok([0, 1, 2, 1])]),
        (Domain, "pieces[0].rect".into())
    );
    // Cells that do not form a grid: a T-junction, an overlap, a hole.
    assert_eq!(
        run(vec![ok([0, 1, 0, 1]), ok([1, 2, 0, 1]), ok([0, 2, 1, 2])]),
        (Domain, "pieces[2].rect".into())
    );
    assert_eq!(
        run(vec![ok([0, 1, 0, 1]), ok([1, 2, 0, 1]), ok([1, 2, 0, 1])]),
        (Domain, "pieces[2].rect".into())
    );
    assert_eq!(
        run(vec![ok([0, 1, 0, 1]), ok([1, 2, 1, 2])]),
        (Domain, "pieces".into())
    );
    // A bidegree above (1, 1); a different dimension.
    assert_eq!(
        run(vec![
            ok([0, 1, 0, 1]),
            piece([1, 2, 0, 1], &[&[0, 0, 0], &[0, 0, 7]])
        ]),
        (Degree, "pieces[1].coefficients[1][2]".into())
    );
    let mut other = ok([1, 2, 0, 1]);
    other.surface = PowerSurface::new(vec![vec![vec![q(1, 1), q(1, 1)]]]).unwrap();
    assert_eq!(
        run(vec![ok([0, 1, 0, 1]), other]),
        (Dimension, "pieces[1].coefficients[0][0]".into())
    );
    // Leading zero coefficients beyond the bidegree are fine.
    assert!(bspline_surface_from_pieces(
        (1, 1),
        &[piece([0, 1, 0, 1], &[&[1, 1, 0], &[1, 0, 0], &[0, 0, 0]])]
    )
    .is_ok());
}

#[test]
fn bad_nurbs_surfaces_are_refused_with_kind_and_field() {
    use ErrorKind::*;
    let k = ints(&[0, 0, 1, 1]);
    let pts = scalar_grid(&[&[0, 1], &[2, 3]]);
    let w = |rows: &[&[i64]]| -> Vec<Vec<Rational>> { rows.iter().map(|r| ints(r)).collect() };
    let new = |pts: Grid, weights| {
        RationalBSplineSurface::new((1, 1), k.clone(), k.clone(), pts, weights)
    };
    assert_eq!(
        kind_and_field(new(pts.clone(), w(&[&[1, 1], &[1, 0]]))),
        (ZeroWeight, "weights[1][1]".into())
    );
    assert_eq!(
        kind_and_field(new(pts.clone(), w(&[&[1, 1]]))),
        (Shape, "weights".into())
    );
    assert_eq!(
        kind_and_field(new(pts.clone(), w(&[&[1, 1], &[1]]))),
        (Shape, "weights[1]".into())
    );
    assert_eq!(
        kind_and_field(new(scalar_grid(&[&[0, 1], &[2]]), w(&[&[1, 1], &[1, 1]]))),
        (Shape, "points[1]".into())
    );
    assert_eq!(
        kind_and_field(RationalBSplineSurface::new(
            (2, 1),
            k.clone(),
            k.clone(),
            pts.clone(),
            w(&[&[1, 1], &[1, 1]])
        )),
        (Shape, "points".into())
    );
    // w(u, v) = 1 - 2u vanishes on u = 1/2: evaluation divides by zero there, and inserting
    // u = 1/2 makes a de Boor point of weight zero.
    let f = new(pts.clone(), w(&[&[1, 1], &[-1, -1]])).unwrap();
    assert_eq!(
        kind_and_field(f.eval(&q(1, 2), &q(1, 3))),
        (ZeroWeight, "(u, v)".into())
    );
    // At (1/4, 0): N = 3/4 * 0 + 1/4 * (-1) * 2 = -1/2 over w = 1/2.
    assert_eq!(f.eval(&q(1, 4), &q(0, 1)).unwrap(), vec![q(-1, 1)]);
    assert_eq!(
        kind_and_field(f.insert_u_knot(&q(1, 2))),
        (ZeroWeight, "x".into())
    );
    assert_eq!(
        kind_and_field(f.eval(&q(2, 1), &q(0, 1))),
        (Domain, "u".into())
    );
    // Quadratic in u with weights 1, 1, -1, 1 on knots 0,0,0,1,2,2,2: the Bézier weight at the
    // knot 1 is (1 + (-1)) / 2 = 0.
    let g = RationalBSplineSurface::new(
        (2, 1),
        ints(&[0, 0, 0, 1, 2, 2, 2]),
        k.clone(),
        scalar_grid(&[&[0, 0], &[1, 1], &[2, 2], &[3, 3]]),
        w(&[&[1, 1], &[1, 1], &[-1, -1], &[1, 1]]),
    )
    .unwrap();
    let e = g.bezier_patches().unwrap_err();
    assert_eq!((e.kind, e.field.as_str()), (ZeroWeight, "weights"));
    assert!(e.message.contains("[0, 1] x [0, 1]"), "{e}");
    assert_eq!(
        kind_and_field(g.eval(&q(1, 1), &q(1, 2))),
        (ZeroWeight, "(u, v)".into())
    );
    // The homogeneous form needs a weight coordinate, and non-zero weights.
    let scalar = BSplineSurface::new((1, 1), k.clone(), k.clone(), pts.clone()).unwrap();
    assert_eq!(
        kind_and_field(RationalBSplineSurface::from_homogeneous(scalar)),
        (Dimension, "homogeneous".into())
    );
    let zero = BSplineSurface::new(
        (1, 1),
        k.clone(),
        k.clone(),
        vec![
            vec![vec![q(0, 1), q(1, 1)], vec![q(1, 1), q(1, 1)]],
            vec![vec![q(0, 1), q(1, 1)], vec![q(1, 1), q(0, 1)]],
        ],
    )
    .unwrap();
    assert_eq!(
        kind_and_field(RationalBSplineSurface::from_homogeneous(zero)),
        (ZeroWeight, "control_points[1][1]".into())
    );
}

#[test]
fn bicubic_by_biquadratic_worked_example() {
    // z = u^2 v, plus (u - 1)^3 v on u >= 1 (C^2 across u = 1) and (v - 1)^2 u on v >= 1
    // (C^1 across v = 1); x = u and y = v everywhere. Knots: 1 once in u (3 - 2), once in v
    // (2 - 1).
    let cell = |i: usize, j: usize| {
        let mut z = vec![vec![q(0, 1); 3]; 4];
        z[2][1] = q(1, 1);
        if i == 1 {
            // (u - 1)^3 v = (u^3 - 3u^2 + 3u - 1) v
            for (e, c) in [(0, -1), (1, 3), (2, -3), (3, 1)] {
                z[e][1] = &z[e][1] + q(c, 1);
            }
        }
        if j == 1 {
            // (v - 1)^2 u = (v^2 - 2v + 1) u
            for (g, c) in [(0, 1), (1, -2), (2, 1)] {
                z[1][g] = &z[1][g] + q(c, 1);
            }
        }
        let grid: Grid = (0..4)
            .map(|e| {
                (0..3)
                    .map(|g| {
                        let x = q((e == 1 && g == 0) as i64, 1);
                        let y = q((e == 0 && g == 1) as i64, 1);
                        vec![x, y, z[e][g].clone()]
                    })
                    .collect()
            })
            .collect();
        SurfacePiece {
            rect: [
                q(i as i64, 1),
                q(i as i64 + 1, 1),
                q(j as i64, 1),
                q(j as i64 + 1, 1),
            ],
            surface: PowerSurface::new(grid).unwrap(),
        }
    };
    let pieces = vec![cell(0, 0), cell(1, 0), cell(0, 1), cell(1, 1)];
    let f = bspline_surface_from_pieces((3, 2), &pieces).unwrap();
    assert_eq!(f.u_knots(), ints(&[0, 0, 0, 0, 1, 2, 2, 2, 2]).as_slice());
    assert_eq!(f.v_knots(), ints(&[0, 0, 0, 1, 2, 2, 2]).as_slice());
    // x = u and y = v: the de Boor points' first coordinates are the Greville abscissae
    // (t_{k+1} + t_{k+2} + t_{k+3}) / 3 and (s_{l+1} + s_{l+2}) / 2.
    let (t, s) = (f.u_knots(), f.v_knots());
    for (kk, row) in f.control_points().enumerate() {
        for (l, d) in row.iter().enumerate() {
            assert_eq!(d[0], (&t[kk + 1] + &t[kk + 2] + &t[kk + 3]) / q(3, 1));
            assert_eq!(d[1], (&s[l + 1] + &s[l + 2]) / q(2, 1));
        }
    }
    let x = (q(3, 2), q(1, 2));
    let value = f.eval(&x.0, &x.1).unwrap();
    assert_eq!(value, pieces[1].surface.eval(&x.0, &x.1));
    let sh = |p: &[Rational]| Json::strings(p);
    insta::with_settings!({snapshot_path => concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"), prepend_module_to_snapshot => false}, {
        insta::assert_snapshot!("spline_surface_bicubic_biquadratic", Json::object([
            ("degree", Json::strings(&[3, 2])),
            ("u_knots", sh(f.u_knots())),
            ("v_knots", sh(f.v_knots())),
            ("de_boor_points", Json::array(f.control_points().map(|row| Json::array(row.iter().map(&sh))))),
            ("bezier_cells", Json::array(f.bezier_patches().iter().map(|c| sh(&c.rect)))),
            ("F(3/2, 1/2)", sh(&value)),
        ]).pretty());
    });
}
