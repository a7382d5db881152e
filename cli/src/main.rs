//! The `blossom` binary: everything is in [`blossom_cli::jobs`].

fn main() {
    std::process::exit(blossom_cli::jobs::main());
}
