blossom::restriction!(vis = , name = restrict_cubic, shape = curve, degree = 3);

fn main() {}
