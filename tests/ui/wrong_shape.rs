blossom::restriction!(name = restrict_circle, shape = circle, degree = 3);

fn main() {}
