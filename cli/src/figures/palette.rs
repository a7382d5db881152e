//! The colours of the pictures. The dot colours (control points, marked points) are saturated
//! and used by nothing else: the frame, grid and axes are greys, curves and meshes are the
//! muted colours below, so a pixel of a dot colour can only belong to a dot.

use super::scene::Rgb;

/// The page.
pub const BACKGROUND: Rgb = Rgb(255, 255, 255);
/// Titles, legends and axis text.
pub const TEXT: Rgb = Rgb(20, 20, 20);

/// The mesh of the first surface of a picture, and the first curve.
pub const MESH: Rgb = Rgb(96, 112, 140);
/// The mesh of the second surface of a picture.
pub const MESH_2: Rgb = Rgb(150, 118, 80);
/// A control net or polygon.
pub const NET: Rgb = Rgb(110, 110, 110);
/// The second control net or polygon of a picture.
pub const NET_2: Rgb = Rgb(160, 130, 150);
/// A curve computed from its control points.
pub const CURVE: Rgb = Rgb(30, 60, 110);
/// A reference curve (the exact circle, ln t).
pub const REFERENCE: Rgb = Rgb(120, 170, 120);
/// A stretch drawn over curves to single it out (the overlap of two curves).
pub const HIGHLIGHT: Rgb = Rgb(0, 190, 190);

/// The fill of a first region (light), and of a second.
pub const FILL: Rgb = Rgb(170, 200, 235);
/// The fill of a second region, or of a result.
pub const FILL_2: Rgb = Rgb(240, 205, 160);

/// The control points of the first net of a picture.
pub const DOTS: Rgb = Rgb(230, 0, 40);
/// The control points of the second net of a picture.
pub const DOTS_2: Rgb = Rgb(0, 90, 255);
/// Points marked on a curve (the images of the knots).
pub const DOTS_3: Rgb = Rgb(255, 150, 0);

/// Points marked differently from [`DOTS_3`] (tangencies).
pub const DOTS_4: Rgb = Rgb(150, 0, 210);

/// Every dot colour: none is used for anything but dots.
pub const DOT_COLOURS: [Rgb; 4] = [DOTS, DOTS_2, DOTS_3, DOTS_4];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dot_colours_are_used_by_nothing_else() {
        let others = [
            BACKGROUND, TEXT, MESH, MESH_2, NET, NET_2, CURVE, REFERENCE, HIGHLIGHT, FILL, FILL_2,
        ];
        for d in DOT_COLOURS {
            assert!(!others.contains(&d));
        }
    }
}
