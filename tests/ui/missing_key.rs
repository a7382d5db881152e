// The `degree` key is missing.
blossom::restriction!(vis = pub, name = restrict_cubic, shape = curve);

fn main() {}
