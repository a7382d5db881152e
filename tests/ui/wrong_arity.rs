blossom::restriction!(name = restrict_patch, shape = tensor, degree = 3);
blossom::restriction!(name = restrict_cubic, shape = curve, degree = (3, 2));

fn main() {}
blossom::restriction!(name = restrict_bezier_triangle_pair, shape = bezier_triangle, degree = (3, 2));
