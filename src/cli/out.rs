//! Terminal output of every sub-command: results go to stdout through `outln!`, which
//! returns the write error instead of panicking like `println!`; diagnostics go to stderr
//! through `errln!`, best effort (a closed stderr is no reason to fail a run). A reader that
//! closes stdout early (`biped ... | head -1`) ends the run as a quiet success: `main` checks
//! the returned error with [`is_broken_pipe`].

use std::error::Error;
use std::fmt;
use std::io::{self, Write};

/// Writes one formatted line to stdout; evaluates to `std::io::Result<()>`.
macro_rules! outln {
    () => {
        $crate::cli::out::line(format_args!(""))
    };
    ($($arg:tt)*) => {
        $crate::cli::out::line(format_args!($($arg)*))
    };
}

/// Writes one formatted line to stderr, ignoring write errors.
macro_rules! errln {
    ($($arg:tt)*) => {
        $crate::cli::out::diagnostic(format_args!($($arg)*))
    };
}

pub(crate) use {errln, outln};

/// Writes `args` and a newline to the locked stdout.
pub fn line(args: fmt::Arguments) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_fmt(args)?;
    out.write_all(b"\n")
}

/// Writes `args` and a newline to the locked stderr; a failed write is dropped.
pub fn diagnostic(args: fmt::Arguments) {
    let mut err = io::stderr().lock();
    let _ = err.write_fmt(args).and_then(|_| err.write_all(b"\n"));
}

/// Writes `text` to stderr without a newline (progress lines), ignoring write errors.
pub fn progress(text: &str) {
    let mut err = io::stderr().lock();
    let _ = err.write_all(text.as_bytes()).and_then(|_| err.flush());
}

/// Whether `err` or an error in its source chain is a write to a closed pipe (also when
/// wrapped in a `serde_json::Error`, whose chain skips the I/O error itself).
pub fn is_broken_pipe(err: &(dyn Error + 'static)) -> bool {
    let mut next = Some(err);
    while let Some(e) = next {
        let kind = match (
            e.downcast_ref::<io::Error>(),
            e.downcast_ref::<serde_json::Error>(),
        ) {
            (Some(io), _) => Some(io.kind()),
            (None, Some(json)) => json.io_error_kind(),
            (None, None) => None,
        };
        if kind == Some(io::ErrorKind::BrokenPipe) {
            return true;
        }
        // A wrapping `io::Error`'s `source()` is its inner error's source: look inside too.
        let inner = e.downcast_ref::<io::Error>().and_then(io::Error::get_ref);
        if inner.is_some_and(|i| is_broken_pipe(i)) {
            return true;
        }
        next = e.source();
    }
    false
}

/// A clap error in one line: the range checks' own message for a rejected value (it names
/// the option and the valid range), else clap's first paragraph and tips, without the usage.
pub fn clap_error_line(e: &clap::Error) -> String {
    if e.kind() == clap::error::ErrorKind::ValueValidation {
        match std::error::Error::source(e).map(|s| s.to_string()) {
            Some(own) if own.starts_with("--") => return format!("error: {own}"),
            _ => {} // Not a range check: clap's line names the option.
        }
    }
    let text = e.render().to_string();
    let mut parts = Vec::new();
    for (k, para) in text.split("\n\n").enumerate() {
        let joined: Vec<&str> = para
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .collect();
        let joined = joined.join(" ");
        if k == 0 || joined.starts_with("tip:") {
            parts.push(joined);
        }
    }
    parts.join("; ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn broken_pipe_is_found_in_the_chain() {
        let pipe = || io::Error::from(io::ErrorKind::BrokenPipe);
        let boxed: Box<dyn Error> = Box::new(pipe());
        assert!(is_broken_pipe(&*boxed));
        let json: Box<dyn Error> = Box::new(serde_json::Error::io(pipe()));
        assert!(is_broken_pipe(&*json));
        let wrapped = io::Error::other(pipe());
        assert!(is_broken_pipe(&wrapped));
        let other: Box<dyn Error> = Box::new(io::Error::from(io::ErrorKind::NotFound));
        assert!(!is_broken_pipe(&*other));
        let text: Box<dyn Error> = "broken pipe".into();
        assert!(!is_broken_pipe(&*text));
    }
}
