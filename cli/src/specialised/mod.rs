//! Degree-specialised restriction: the functions that `blossom::restriction!` generates from
//! the closed forms (3), (9), (14), carried by the crate for a grid of degrees, with
//!
//! * a dispatch from the library types ([`restrict_curve_specialised`],
//!   [`restrict_tensor_specialised`], [`restrict_triangle_specialised`]; `None` for a degree
//!   that is not carried, see [`carried_degrees`]), used by `blossom restrict --method specialised`;
//! * the proofs ([`proof_table`]): every carried evaluator of the proof grid, run on symbolic
//!   polynomials, is identical as a polynomial to the subset-sum definition (eqs. (2), (8),
//!   (13)) and to the polarisation formula of the inverse-relations paper;
//! * the source that the macro generates, as text ([`expand_source`], [`expand_command`]),
//!   printed by `blossom expand curve 3`.
//!
//! The carried set: curves of degree 1..=16, tensor patches (n, m) with 0 <= n, m <= 5 and
//! triangles (n, m) with 0 <= n, m <= 4, (n, m) = (0, 0) excepted.
//!
//! Points of the library types have a run-time dimension while the generated functions take
//! it as a const generic `D`: the dispatch instantiates each evaluator once, with `D = 1` on
//! the ring [`Scalar`] (any of f64, exact rationals and symbolic polynomials, operations out of
//! line), and calls it once per coordinate. This keeps one instantiation of the large grid for
//! all number types; the price is that the scalar weights are recomputed for each coordinate
//! and each ring operation is a call and a `match`. Callers
//! that know `D` at compile time call the generated functions of [`grid`] directly (or
//! generate their own with the macro), as the benchmarks do.
//!
//! The grid, its dispatch and its proofs are behind the default feature `carried-grid` (they
//! dominate the build time of the crate); the macro and `blossom expand` are always there.
//!
//! ```
//! # #[cfg(feature = "carried-grid")] {
//! use blossom_cli::specialised::{grid, restrict_curve_specialised};
//! use blossom::{restrict_power_curve, Method, PowerCurve, Rational};
//!
//! let q = |n: i64| Rational::from_integer(n.into());
//! let curve = PowerCurve::new(vec![vec![q(1), q(2)], vec![q(-3), q(0)], vec![q(0), q(5)]])?;
//! let w = restrict_curve_specialised(&curve, &q(-1), &q(2)).expect("degree 2 is carried");
//! assert_eq!(w, restrict_power_curve(&curve, &q(-1), &q(2), Method::Definition));
//! // The generated function itself, on fixed-size arrays of 3-D f64 points:
//! let w = grid::curve_1(&[[1.0, 2.0, 3.0], [1.0, 1.0, 1.0]], &0.0, &2.0);
//! assert_eq!(w, [[1.0, 2.0, 3.0], [3.0, 4.0, 5.0]]);
//! # }
//! # Ok::<(), blossom::Error>(())
//! ```

#[cfg(feature = "carried-grid")]
mod proof_grid;

#[cfg(feature = "carried-grid")]
pub use blossom_grid::{
    grid, restrict_bezier_curve_specialised, restrict_bezier_tensor_specialised,
    restrict_bezier_triangle_specialised, restrict_curve_specialised,
    restrict_power_triangle_specialised, restrict_tensor_specialised,
    restrict_triangle_specialised,
};
pub use blossom_grid::{Carried, Scalar};
#[cfg(feature = "carried-grid")]
pub use proof_grid::{
    proof_table, proof_table_text, prove_bezier_curve, prove_curve, prove_tensor, prove_triangle,
    ProofRow,
};

use blossom::Error;
pub use blossom_codegen::{Shape, MAX_CURVE_DEGREE, MAX_TENSOR_DEGREE, MAX_TRIANGLE_DEGREE};

/// Describes the carried degrees, for the error message of a degree that is not carried.
pub fn carried_degrees() -> &'static str {
    "curves of degree 1..=16, tensor patches (n, m) with 0 <= n, m <= 5 and triangular patches \
     (n, m) with 0 <= n, m <= 4, (n, m) = (0, 0) excepted; triangular arrays (\"total_degree\") of \
     total degree 1..=6; Bézier curves of degree 1..=16, \
     Bézier tensor-product patches (n, m) with 0 <= n, m <= 4, (n, m) = (0, 0) excepted, and \
     Bézier triangular patches of degree 1..=6"
}

/// Whether the binary carries a specialised evaluator for `shape`.
pub fn carries(shape: Shape) -> bool {
    match shape {
        Shape::Curve(n) => (1..=16).contains(&n),
        Shape::Tensor(n, m) => n <= 5 && m <= 5 && (n, m) != (0, 0),
        Shape::Triangle(n, m) => n <= 4 && m <= 4 && (n, m) != (0, 0),
        Shape::BezierCurve(n) => (1..=16).contains(&n),
        Shape::BezierTensor(n, m) => n <= 4 && m <= 4 && (n, m) != (0, 0),
        Shape::BezierTriangle(n) | Shape::TriangleTotal(n) => (1..=6).contains(&n),
    }
}

/// The function `blossom::restriction!` generates for `shape` (public, named
/// `restrict_curve_3`, `restrict_tensor_3_2`, ...), formatted as Rust source that compiles on
/// its own in a crate depending on `blossom`. Fails for a degree above the macro's limit.
pub fn expand_source(shape: Shape) -> Result<String, Error> {
    shape
        .check_limit()
        .map_err(|msg| Error::new("degree", msg))?;
    let (kw, degree) = (shape.keyword(), shape.degree_text());
    let header = format!(
        "// `blossom expand {shape}`: what\n\
         // `blossom::restriction!(vis = pub, name = {}, shape = {kw}, degree = {degree});` generates.\n",
        shape.default_name()
    );
    Ok(header + &blossom_codegen::source(&blossom_codegen::Spec::public(shape)))
}

/// Parses the arguments of `blossom expand` (`curve 3`, `tensor 3 2`, `triangle 3 2`) and
/// returns [`expand_source`] of them. Errors name the offending argument.
pub fn expand_command<S: AsRef<str>>(args: &[S]) -> Result<String, Error> {
    let args: Vec<&str> = args.iter().map(AsRef::as_ref).collect();
    let usage = "expected `curve N`, `tensor N M`, `triangle N M`, `triangle-total N`, \
                 `bezier-curve N`, `bezier-tensor N M` or `bezier-triangle N`";
    let Some((&kw, degrees)) = args.split_first() else {
        return Err(Error::new("shape", usage));
    };
    let want = match kw {
        "curve" | "triangle-total" | "bezier-curve" | "bezier-triangle" => 1,
        "tensor" | "triangle" | "bezier-tensor" => 2,
        other => {
            return Err(Error::new(
                "shape",
                format!("unknown shape `{other}`: {usage}"),
            ))
        }
    };
    if degrees.len() != want {
        return Err(Error::new(
            "degree",
            format!(
                "`{kw}` takes {want} degree{}, found {}",
                if want == 1 { "" } else { "s" },
                degrees.len()
            ),
        ));
    }
    let mut ds = Vec::new();
    for (k, d) in degrees.iter().enumerate() {
        ds.push(d.parse::<usize>().map_err(|_| {
            Error::new(
                format!("degree[{k}]"),
                format!("expected a non-negative integer, found `{d}`"),
            )
        })?);
    }
    let shape = match kw {
        "curve" => Shape::Curve(ds[0]),
        "tensor" => Shape::Tensor(ds[0], ds[1]),
        "triangle" => Shape::Triangle(ds[0], ds[1]),
        "bezier-curve" => Shape::BezierCurve(ds[0]),
        "bezier-tensor" => Shape::BezierTensor(ds[0], ds[1]),
        "triangle-total" => Shape::TriangleTotal(ds[0]),
        _ => Shape::BezierTriangle(ds[0]),
    };
    expand_source(shape)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expand_command_names_the_bad_argument() {
        assert_eq!(expand_command(&["circle", "3"]).unwrap_err().field, "shape");
        assert_eq!(
            expand_command(&["tensor", "3"]).unwrap_err().field,
            "degree"
        );
        assert_eq!(
            expand_command(&["curve", "-1"]).unwrap_err().field,
            "degree[0]"
        );
        assert_eq!(
            expand_command(&["curve", "99"]).unwrap_err().field,
            "degree"
        );
        assert!(expand_command::<&str>(&[]).is_err());
        assert_eq!(
            expand_command(&["bezier-triangle", "3", "2"])
                .unwrap_err()
                .field,
            "degree"
        );
        assert_eq!(
            expand_command(&["bezier-triangle", "7"]).unwrap_err().field,
            "degree"
        );
        let src = expand_command(&["bezier-curve", "3"]).unwrap();
        assert!(src.contains("pub fn restrict_bezier_curve_3<T: ::blossom::Ring, const D: usize>("));
        let src = expand_command(&["curve", "3"]).unwrap();
        assert!(src.contains("pub fn restrict_curve_3<T: ::blossom::Ring, const D: usize>("));
    }

    // The scalar ring of the grid (crate `blossom-grid`, which has no tests of its own).
    use blossom::{Poly, Rational, Ring};

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn constants_take_the_type_of_the_other_operand() {
        let half = Scalar::one().scale_frac(1, 2);
        assert_eq!(half, Scalar::Exact(q(1, 2)));
        assert_eq!(half.mul(&3.0.wrap()), Scalar::F64(1.5));
        assert_eq!(q(3, 1).wrap().mul(&half), Scalar::Exact(q(3, 2)));
        let x = Poly::var("x");
        let got = Poly::unwrap(half.mul(&x.wrap()).add(&Scalar::one()));
        assert_eq!(got, x.scale(&q(1, 2)).add(&Poly::one()));
        assert_eq!(f64::unwrap(Scalar::Exact(q(1, 4))), 0.25);
        assert_eq!(Rational::unwrap(Scalar::F64(0.375)), q(3, 8));
    }

    #[test]
    fn each_type_keeps_its_arithmetic() {
        // 0.1 + 0.2 rounds in f64 and is exact in rationals.
        let f = f64::unwrap(0.1.wrap().add(&0.2.wrap()));
        assert_eq!(f, 0.1 + 0.2);
        let r = Rational::unwrap(q(1, 10).wrap().add(&q(2, 10).wrap()));
        assert_eq!(r, q(3, 10));
        assert!(Scalar::F64(1.0).sub(&Scalar::F64(1.0)).is_zero());
        assert_eq!(Scalar::F64(2.0).neg(), Scalar::F64(-2.0));
    }
}
