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

/// Runs `blossom restrict ARGS` on the JSON `job`.
pub fn run_restrict(args: &[&str], job: &serde_json::Value) -> Run {
    let mut all = vec!["restrict"];
    all.extend_from_slice(args);
    run_binary(&all, job.to_string().as_bytes())
}

/// The answer of `job` under `args`, checking the contract: exit 0, one line of JSON, nothing
/// on standard error.
pub fn restrict_answer(args: &[&str], job: &serde_json::Value) -> serde_json::Value {
    let r = run_restrict(args, job);
    assert_eq!(r.code, 0, "job {job} ({args:?}): {}", r.stderr);
    assert!(r.stderr.is_empty());
    assert_eq!(r.stdout.lines().count(), 1, "{}", r.stdout);
    serde_json::from_str(&r.stdout).expect("JSON")
}

/// The error line of `job` refused under `args`, checking the contract: exit 2, empty
/// standard output, one line `error: ...`.
pub fn restrict_error(args: &[&str], job: &serde_json::Value) -> String {
    let r = run_restrict(args, job);
    assert_eq!(r.code, 2, "job {job} ({args:?}) was accepted: {}", r.stdout);
    assert!(r.stdout.is_empty(), "{}", r.stdout);
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
    assert!(r.stderr.starts_with("error: "), "{}", r.stderr);
    r.stderr.trim_end().to_string()
}
