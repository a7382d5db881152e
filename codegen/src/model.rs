//! The plain data model of the macro: what the parser reads ([`RawInput`]) and what the validator
//! makes of it ([`Spec`]).

use proc_macro2::{Ident, TokenStream};
use std::fmt;
use syn::{Attribute, Token, Visibility};

/// The highest curve degree `n` the macro accepts (see the crate docs for the measurement).
pub const MAX_CURVE_DEGREE: usize = 24;
/// The highest degree in each variable, `n` and `m`, of a tensor-product patch.
pub const MAX_TENSOR_DEGREE: usize = 10;
/// The highest total degree `N = n + m` of a triangular patch.
pub const MAX_TRIANGLE_DEGREE: usize = 8;
/// The highest degree `N` of a triangular Bézier patch (its power form has (N+1)(N+2)/2
/// coefficients, about twice as many as the (n, m) grid of the same total degree).
pub const MAX_BEZIER_TRIANGLE_DEGREE: usize = 6;

/// What to generate: the shape of the domain and the degree.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Shape {
    /// A curve C(u) = sum_{i=0}^n c_i u^i of degree `n`, restricted to an interval (eq. (3)).
    Curve(usize),
    /// A surface of bidegree `(n, m)` restricted to a rectangle (eq. (9)).
    Tensor(usize, usize),
    /// A surface sum_{i<=n, j<=m} c_ij u^i v^j of total degree `N = n + m` restricted to a
    /// triangle (eq. (14)).
    Triangle(usize, usize),
    /// A surface sum_{i+j<=N} c_ij u^i v^j given by its triangular array, of total degree `N`,
    /// restricted to a triangle (eq. (14) over the array).
    TriangleTotal(usize),
    /// A Bézier curve of degree `n` over [0, 1], given by its control points, restricted to an
    /// interval (forward differences, then eq. (3) without its denominators).
    BezierCurve(usize),
    /// A tensor-product Bézier patch of bidegree `(n, m)` over [0, 1]^2 restricted to a
    /// rectangle (two-way forward differences, then eq. (9) without its denominators).
    BezierTensor(usize, usize),
    /// A triangular Bézier patch of degree `N` restricted to a sub-triangle (two-way forward
    /// differences, then eq. (14) over the coefficients i + j <= N without its denominators).
    BezierTriangle(usize),
}

impl Shape {
    /// The keyword of the shape in the macro input: `curve`, `tensor` or `triangle`.
    pub fn keyword(self) -> &'static str {
        match self {
            Shape::Curve(_) => "curve",
            Shape::Tensor(..) => "tensor",
            Shape::Triangle(..) => "triangle",
            Shape::TriangleTotal(_) => "triangle_total",
            Shape::BezierCurve(_) => "bezier_curve",
            Shape::BezierTensor(..) => "bezier_tensor",
            Shape::BezierTriangle(_) => "bezier_triangle",
        }
    }

    /// Whether the input is a Bézier net (control points) rather than power coefficients.
    pub fn is_bezier(self) -> bool {
        matches!(
            self,
            Shape::BezierCurve(_) | Shape::BezierTensor(..) | Shape::BezierTriangle(_)
        )
    }

    /// The degree as written in the macro input: `3` for a curve, `(3, 2)` for a surface.
    pub fn degree_text(self) -> String {
        match self {
            Shape::Curve(n)
            | Shape::BezierCurve(n)
            | Shape::BezierTriangle(n)
            | Shape::TriangleTotal(n) => n.to_string(),
            Shape::Tensor(n, m) | Shape::Triangle(n, m) | Shape::BezierTensor(n, m) => {
                format!("({n}, {m})")
            }
        }
    }

    /// The default name of the generated function, e.g. `restrict_tensor_3_2`.
    pub fn default_name(self) -> String {
        match self {
            Shape::Curve(n) => format!("restrict_curve_{n}"),
            Shape::Tensor(n, m) => format!("restrict_tensor_{n}_{m}"),
            Shape::Triangle(n, m) => format!("restrict_triangle_{n}_{m}"),
            Shape::TriangleTotal(n) => format!("restrict_triangle_total_{n}"),
            Shape::BezierCurve(n) => format!("restrict_bezier_curve_{n}"),
            Shape::BezierTensor(n, m) => format!("restrict_bezier_tensor_{n}_{m}"),
            Shape::BezierTriangle(n) => format!("restrict_bezier_triangle_{n}"),
        }
    }

    /// `Err(message)` when the degree is above the documented limit of its shape.
    pub fn check_limit(self) -> Result<(), String> {
        match self {
            Shape::Curve(n) | Shape::BezierCurve(n) if n > MAX_CURVE_DEGREE => Err(format!(
                "curve degree {n} is above the limit {MAX_CURVE_DEGREE}: the unrolled eq. (3) \
                 grows like n^3/6 terms (see the blossom-macros docs for the measured sizes)"
            )),
            Shape::Tensor(n, m) | Shape::BezierTensor(n, m)
                if n > MAX_TENSOR_DEGREE || m > MAX_TENSOR_DEGREE =>
            {
                Err(format!(
                "tensor degree ({n}, {m}) is above the limit {MAX_TENSOR_DEGREE} in each variable: \
                 the unrolled eq. (9) grows like n m (n + m) terms (see the blossom-macros docs)"
                ))
            }
            Shape::Triangle(n, m) if n + m > MAX_TRIANGLE_DEGREE => Err(format!(
                "triangle total degree N = {n} + {m} = {} is above the limit {MAX_TRIANGLE_DEGREE}: \
                 the unrolled eq. (14) grows like N^4 terms (see the blossom-macros docs)",
                n + m
            )),
            Shape::TriangleTotal(n) if n > MAX_TRIANGLE_DEGREE => Err(format!(
                "triangle total degree N = {n} is above the limit {MAX_TRIANGLE_DEGREE}: the \
                 unrolled eq. (14) grows like N^5 terms (see the blossom-macros docs)"
            )),
            Shape::BezierTriangle(n) if n > MAX_BEZIER_TRIANGLE_DEGREE => Err(format!(
                "Bézier triangle degree {n} is above the limit {MAX_BEZIER_TRIANGLE_DEGREE}: its \
                 power form has (N+1)(N+2)/2 coefficients and the unrolled eq. (14) grows like \
                 N^4 terms (see the blossom-macros docs)"
            )),
            _ => Ok(()),
        }
    }
}

impl fmt::Display for Shape {
    /// `curve 3`, `tensor 3 2`, `triangle 3 2` (the arguments of `blossom expand`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Shape::Curve(n) => write!(f, "curve {n}"),
            Shape::Tensor(n, m) => write!(f, "tensor {n} {m}"),
            Shape::Triangle(n, m) => write!(f, "triangle {n} {m}"),
            Shape::TriangleTotal(n) => write!(f, "triangle-total {n}"),
            Shape::BezierCurve(n) => write!(f, "bezier-curve {n}"),
            Shape::BezierTensor(n, m) => write!(f, "bezier-tensor {n} {m}"),
            Shape::BezierTriangle(n) => write!(f, "bezier-triangle {n}"),
        }
    }
}

/// A validated macro input: everything the expansion needs.
#[derive(Clone)]
pub struct Spec {
    /// Outer attributes (doc comments, `#[inline]`, ...) copied onto the generated function.
    pub attrs: Vec<Attribute>,
    /// Visibility of the generated function (private when the `vis` key is absent).
    pub vis: Visibility,
    /// Name of the generated function.
    pub name: Ident,
    /// Shape and degree.
    pub shape: Shape,
}

impl fmt::Debug for Spec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use quote::ToTokens;
        f.debug_struct("Spec")
            .field("attrs", &self.attrs.len())
            .field("vis", &self.vis.to_token_stream().to_string())
            .field("name", &self.name.to_string())
            .field("shape", &self.shape)
            .finish()
    }
}

impl Spec {
    /// A public function with the default name of `shape` and no extra attributes.
    pub fn public(shape: Shape) -> Spec {
        Spec {
            attrs: Vec::new(),
            vis: syn::parse_quote!(pub),
            name: Ident::new(&shape.default_name(), proc_macro2::Span::call_site()),
            shape,
        }
    }
}

/// The macro input as written: leading attributes, then `key = value` entries separated by
/// commas. Values are kept as raw tokens (with their spans) for the validator to interpret.
pub struct RawInput {
    /// Leading outer attributes.
    pub attrs: Vec<Attribute>,
    /// The entries in source order.
    pub entries: Vec<RawEntry>,
}

/// One `key = value` entry.
pub struct RawEntry {
    /// The key, e.g. `degree`.
    pub key: Ident,
    /// The `=` (its span locates an empty value).
    pub eq: Token![=],
    /// The value tokens up to the next top-level comma.
    pub value: TokenStream,
}
