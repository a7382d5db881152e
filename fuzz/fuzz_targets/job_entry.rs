//! `blossom_cli::fuzzing::job_entry`: the whole target and its contracts live there, so that the
//! replay test of the corpus runs the same code.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| blossom_cli::fuzzing::job_entry(data));
