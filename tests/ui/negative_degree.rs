blossom::restriction!(name = restrict_patch, shape = tensor, degree = (3, -1));

fn main() {}
