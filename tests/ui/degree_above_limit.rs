blossom::restriction!(name = restrict_big, shape = curve, degree = 25);
blossom::restriction!(name = restrict_big_patch, shape = tensor, degree = (2, 11));
blossom::restriction!(name = restrict_big_triangle, shape = triangle, degree = (5, 4));

fn main() {}
blossom::restriction!(name = restrict_big_bezier_triangle, shape = bezier_triangle, degree = 7);
