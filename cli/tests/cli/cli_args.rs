//! The command line's arguments parsed in process (`blossom_cli::jobs::args::parse`): defaults
//! and values, every error naming its argument, the nearest name for a typing slip, the help
//! texts against the code's lists.

use blossom::Error;
use blossom::Method;
use blossom_cli::jobs::args::*;
use std::ffi::OsString;
use std::path::PathBuf;

fn parse_strs(args: &[&str]) -> Result<Command, Error> {
    let args: Vec<OsString> = args.iter().map(OsString::from).collect();
    parse(&args)
}

#[test]
fn defaults_and_values() {
    let verify = |json, verbose| Command::Verify { json, verbose };
    assert_eq!(parse_strs(&[]).unwrap(), verify(false, false));
    assert_eq!(
        parse_strs(&["verify", "--json"]).unwrap(),
        verify(true, false)
    );
    assert_eq!(
        parse_strs(&["verify", "--verbose", "--json"]).unwrap(),
        verify(true, true)
    );
    assert_eq!(
        parse_strs(&["figures"]).unwrap(),
        Command::Figures {
            out: PathBuf::from("figures")
        }
    );
    assert_eq!(
        parse_strs(&["figures", "--out=pics"]).unwrap(),
        Command::Figures {
            out: PathBuf::from("pics")
        }
    );
    let Command::Check(c) = parse_strs(&["check", "--per-point", "--max-work", "1e6"]).unwrap()
    else {
        panic!("check")
    };
    assert!(c.per_point);
    assert_eq!((c.input, c.limits.max_work), (None, 1_000_000));
    let Command::Restrict(o) = parse_strs(&["restrict"]).unwrap() else {
        panic!("restrict")
    };
    assert_eq!(o.input, None);
    assert_eq!(o.arithmetic, Arithmetic::Exact);
    assert_eq!(o.method, MethodChoice::Library(Method::Bulk));
    assert_eq!(o.method, MethodChoice::default());
    let Command::Restrict(o) = parse_strs(&[
        "restrict",
        "--method=bulk",
        "--arithmetic",
        "f64",
        "--input",
        "x.json",
    ])
    .unwrap() else {
        panic!("restrict")
    };
    assert_eq!(o.input, Some(PathBuf::from("x.json")));
    assert_eq!(o.arithmetic, Arithmetic::F64);
    assert_eq!(o.method, MethodChoice::Library(Method::Bulk));
}

#[test]
fn errors_name_the_argument() {
    let field = |args: &[&str]| parse_strs(args).unwrap_err().field;
    assert_eq!(field(&["frob"]), "frob");
    assert_eq!(field(&["restrict", "--frob"]), "--frob");
    assert_eq!(field(&["restrict", "--input"]), "--input");
    assert_eq!(
        field(&["restrict", "--input", "--method", "bulk"]),
        "--input"
    );
    assert_eq!(field(&["restrict", "--method", "x"]), "--method");
    assert_eq!(field(&["restrict", "--arithmetic", "f32"]), "--arithmetic");
    assert_eq!(
        field(&["restrict", "--method", "bulk", "--method", "bulk"]),
        "--method"
    );
    assert_eq!(field(&["restrict", "extra"]), "extra");
    assert_eq!(field(&["verify", "--jsn"]), "--jsn");
    assert_eq!(field(&["expand", "curve", "--x"]), "--x");
    assert_eq!(
        field(&["check", "--per-point", "--per-point"]),
        "--per-point"
    );
    assert_eq!(field(&["check", "--method", "bulk"]), "--method");
    assert_eq!(field(&["figures", "--out"]), "--out");
    assert_eq!(field(&["figures", "--out="]), "--out");
    assert_eq!(field(&["figures", "x"]), "x");
    assert_eq!(field(&["verify", "--verbose=1"]), "--verbose");
}

#[test]
fn mistypes_get_the_nearest_name() {
    let message = |args: &[&str]| parse_strs(args).unwrap_err().to_string();
    assert!(message(&["restirct"]).contains("did you mean \"restrict\"?"));
    assert!(message(&["verfy"]).contains("did you mean \"verify\"?"));
    assert!(message(&["figure"]).contains("did you mean \"figures\"?"));
    assert!(message(&["chek"]).contains("did you mean \"check\"?"));
    assert!(message(&["restrict", "--method", "pyramd"]).contains("did you mean \"pyramid\"?"));
    assert!(
        message(&["restrict", "--method", "closed_form"]).contains("did you mean \"closed-form\"?")
    );
    assert!(message(&["restrict", "--method", "taylor"]).contains("did you mean \"taylor-shift\"?"));
    assert!(message(&["restrict", "--arithmetic", "F64"]).contains("did you mean \"f64\"?"));
    assert!(message(&["restrict", "--metod", "bulk"]).contains("did you mean \"--method\"?"));
    assert!(message(&["verify", "--jsno"]).contains("did you mean \"--json\"?"));
    // Nothing near: no suggestion, the list of names only.
    let far = message(&["restrict", "--method", "newton"]);
    assert!(!far.contains("did you mean"), "{far}");
    assert!(far.contains("closed-form, definition"), "{far}");
    assert!(!message(&["xyz"]).contains("did you mean"));
}

#[test]
fn help_names_every_method() {
    // `--method` accepts the library's methods in the order of `Method::ALL` (the default
    // first), each by its own name, then `specialised`.
    let expected: Vec<&str> = Method::ALL
        .iter()
        .map(|m| m.name())
        .chain(["specialised"])
        .collect();
    let names: Vec<&str> = METHOD_NAMES.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, expected);
    for (name, choice) in METHOD_NAMES {
        if let MethodChoice::Library(method) = choice {
            assert_eq!(method.name(), name);
        }
    }
    // The help lists each on a line of its own, and marks the default.
    for name in &expected {
        assert!(
            RESTRICT_HELP.contains(&format!("\n      {name} ")),
            "restrict --help does not list {name}"
        );
    }
    let default = MethodChoice::default();
    let (default_name, _) = METHOD_NAMES.iter().find(|(_, c)| *c == default).unwrap();
    assert!(RESTRICT_HELP.contains(&format!("\n      {default_name} ")));
    let default_entry = RESTRICT_HELP
        .split(&format!("\n      {default_name} "))
        .nth(1)
        .and_then(|rest| rest.split("\n      ").next())
        .unwrap_or_default();
    assert!(default_entry.contains("(default)"), "{default_entry}");
    assert_eq!(
        RESTRICT_HELP.matches("(default)").count(),
        2,
        "arithmetic and method"
    );
    // The top-level help shows every flag of verify.
    assert!(HELP.contains("blossom verify [--json] [--verbose]"));
    assert!(VERIFY_HELP.contains("blossom verify [--json] [--verbose]"));
    assert!(CHECK_HELP.contains("bulk"));
}

#[test]
fn expand_takes_its_words() {
    assert_eq!(
        parse_strs(&["expand", "tensor", "3", "2"]).unwrap(),
        Command::Expand(vec!["tensor".into(), "3".into(), "2".into()])
    );
    assert_eq!(
        parse_strs(&["expand", "--help"]).unwrap(),
        Command::Help(EXPAND_HELP)
    );
}

#[test]
fn completions_for_each_shell() {
    let run = |args: &[&str]| {
        let args: Vec<OsString> = args.iter().map(OsString::from).collect();
        blossom_cli::jobs::run(&args, &mut &b""[..])
    };
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = run(&["completions", shell]);
        assert_eq!(out.code, 0, "{shell}: {}", out.stderr);
        assert!(
            out.stdout.contains("restrict") && out.stdout.contains("max-work"),
            "{shell}"
        );
    }
    let out = run(&["completions", "bsh"]);
    assert_eq!(out.code, 2);
    assert!(
        out.stderr
            .starts_with("error: bsh: unknown shell (did you mean \"bash\"?)"),
        "{}",
        out.stderr
    );
    let out = run(&["completions"]);
    assert!(
        out.stderr
            .starts_with("error: completions: expected one shell"),
        "{}",
        out.stderr
    );
}
