//! Runs the `blossom` binary of this package (`CARGO_BIN_EXE_blossom` exists only in the
//! integration tests of the package that owns the binary).

use std::io::Write;
use std::process::{Command, Stdio};

/// What one run of the `blossom` binary produced.
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// Runs `blossom ARGS` with `input` on standard input.
pub fn run_binary(args: &[&str], input: &[u8]) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_blossom"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    {
        let mut stdin = child.stdin.take().expect("stdin is piped");
        // The binary may exit before reading (bad arguments): ignore a broken pipe.
        let _ = stdin.write_all(input);
    }
    let out = child.wait_with_output().expect("the binary finishes");
    Run {
        code: out.status.code().expect("an exit code, not a signal"),
        stdout: String::from_utf8(out.stdout).expect("UTF-8 stdout"),
        stderr: String::from_utf8(out.stderr).expect("UTF-8 stderr"),
    }
}
