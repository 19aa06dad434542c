//! A sub-command's options from command-line words (without the program and sub-command
//! names), as other front ends give them (the Python package turns its keywords into these):
//! parsed by the same parser, refused with the same one line as the command line.

use super::out::clap_error_line;
use clap::{Args, Command, FromArgMatches};

/// Parses `words` as the options `A` of sub-command `name`; an error is the line the command
/// line prints, without its `error: ` prefix.
pub fn parse<A, I, S>(name: &'static str, words: I) -> Result<A, String>
where
    A: Args + FromArgMatches,
    I: IntoIterator<Item = S>,
    S: Into<String>,
{
    let line = |e: clap::Error| {
        let line = clap_error_line(&e);
        line.strip_prefix("error: ").unwrap_or(&line).to_string()
    };
    let mut cmd = A::augment_args(Command::new(name).no_binary_name(true));
    let words: Vec<String> = words.into_iter().map(Into::into).collect();
    let matches = cmd.try_get_matches_from_mut(words).map_err(line)?;
    A::from_arg_matches(&matches).map_err(line)
}
