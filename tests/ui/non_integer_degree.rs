blossom::restriction!(name = restrict_cubic, shape = curve, degree = 2.5);

fn main() {}
