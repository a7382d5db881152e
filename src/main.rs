//! The `blossom` binary: everything is in [`blossom::cli`].

fn main() {
    std::process::exit(blossom::cli::main());
}
