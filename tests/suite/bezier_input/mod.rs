//! Restriction of Bézier input (curves, tensor patches, triangles) against de Casteljau's
//! pyramid on the blossom, exactly, symbolically and in f64.

mod arrays;
mod bezier_restrict;
mod subdivide;
