const N: usize = 3;
blossom::restriction!(name = restrict_cubic, shape = curve, degree = N);

fn main() {}
