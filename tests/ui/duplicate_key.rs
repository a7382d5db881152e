blossom::restriction! {
    name = restrict_cubic,
    shape = curve,
    degree = 3,
    degree = 4,
}

fn main() {}
