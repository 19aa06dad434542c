//! The `biped` command line as a library: every sub-command's options, validation and runs,
//! so that other front ends (the Python package `biped`, scripts, tests) run exactly what the
//! command line runs, with the same located error messages.
//!
//! # Example
//!
//! A tenth of a second of the Lola-like biped standing, with the options of
//! `biped simulate` given as words; the summary is what `summary.json` holds.
//!
//! ```
//! use biped::cli::simulate::{parse_args, Prepared};
//!
//! let args = parse_args(["--scenario", "stand", "--duration", "0.1"])?;
//! let done = Prepared::new(&args)?.run(None, &mut |_t, _duration| Ok(())).map_err(|a| a.error)?;
//! let summary = done.summary_json(&[])?;
//! assert_eq!(summary["control_cycles"], 100);
//! assert_eq!(summary["scenario"], "stand");
//!
//! // A bad value is one line naming the option.
//! let bad = Prepared::new(&parse_args(["--duration", "-1"])?).err().unwrap();
//! assert!(bad.to_string().starts_with("--duration:"), "{bad}");
//! # Ok::<(), Box<dyn std::error::Error + Send + Sync>>(())
//! ```

pub mod cli;
