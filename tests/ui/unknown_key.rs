blossom::restriction!(name = restrict_cubic, shape = curve, degre = 3);

fn main() {}
