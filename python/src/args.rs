//! Keyword arguments to a command's own argument struct, through the
//! command line's own parser: each keyword becomes the flag of the same
//! name (`allow_long=True` is `--allow-long`, `method="exact"` is
//! `--method=exact`), and any other keyword a parameter key
//! (`omega1=1.2` is `--set=omega1=1.2`). The arguments, their defaults
//! and their error messages are therefore those of the command line.

use std::cell::RefCell;
use std::thread::LocalKey;

use clap::{ArgAction, Args, Command, FromArgMatches};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyString, PyTuple};

use crate::error::Failure;

/// One command's parser, built once per thread on first use.
pub type Parser = LocalKey<RefCell<Option<Command>>>;

/// The argument struct `A` of command `name` from `kwargs`.
pub fn parse<A: Args + FromArgMatches>(
    parser: &'static Parser,
    name: &'static str,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> Result<A, Failure> {
    parser.with(|cell| {
        let mut cell = cell.borrow_mut();
        let command = cell.get_or_insert_with(|| {
            A::augment_args(Command::new(name).no_binary_name(true)).disable_help_flag(true)
        });
        let argv = match kwargs {
            Some(kwargs) => argv(command, kwargs)?,
            None => Vec::new(),
        };
        let matches = command.try_get_matches_from_mut(argv)?;
        Ok(A::from_arg_matches(&matches)?)
    })
}

/// The command line of `kwargs` for `command`.
fn argv(command: &Command, kwargs: &Bound<'_, PyDict>) -> Result<Vec<String>, Failure> {
    let mut out = Vec::with_capacity(2 * kwargs.len());
    for (key, value) in kwargs.iter() {
        if value.is_none() {
            continue;
        }
        let key: String = key.extract()?;
        if key == "format" {
            return Err(Failure::Usage(
                "format: the module returns the report itself, as Python objects; drop format"
                    .into(),
            ));
        }
        // A shard's part records the command line that made it, for the
        // merge to replay: a Python process has none to record.
        if matches!(key.as_str(), "shard" | "part" | "skip_done") {
            return Err(Failure::Usage(format!(
                "{key}: the module runs whole sweeps; shard them from the command line \
                 (pounding COMMAND ... --shard K/N, then pounding merge)"
            )));
        }
        let flag = key.replace('_', "-");
        let arg = command
            .get_arguments()
            .find(|a| a.get_long() == Some(flag.as_str()) && flag != "set");
        match arg {
            Some(arg) if !arg.get_action().takes_values() => {
                if value.cast::<PyBool>().is_ok_and(|b| b.is_true()) {
                    out.push(format!("--{flag}"));
                } else if !value.is_truthy()? {
                    // False: the flag is not given.
                } else {
                    return Err(Failure::Usage(format!(
                        "{key}: a switch, True or False (got {})",
                        value.repr()?
                    )));
                }
            }
            Some(arg) if matches!(arg.get_action(), ArgAction::Append) && is_sequence(&value) => {
                for item in value.try_iter()? {
                    out.push(format!("--{flag}={}", text(&item?)?));
                }
            }
            Some(_) => out.push(format!("--{flag}={}", text(&value)?)),
            None if key == "set" => {
                let items: Vec<Bound<'_, PyAny>> = if is_sequence(&value) {
                    value.try_iter()?.collect::<PyResult<_>>()?
                } else {
                    vec![value]
                };
                for item in items {
                    out.push(format!("--set={}", text(&item)?));
                }
            }
            None => out.push(format!("--set={key}={}", text(&value)?)),
        }
    }
    Ok(out)
}

fn is_sequence(value: &Bound<'_, PyAny>) -> bool {
    value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>()
}

/// A value as the command line would have it: a string as it is, a
/// number as Python writes it (the shortest form that reads back the same
/// float), a list or tuple as its items joined by commas.
fn text(value: &Bound<'_, PyAny>) -> Result<String, Failure> {
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(s.to_cow()?.into_owned());
    }
    if is_sequence(value) {
        let items: Vec<String> = value
            .try_iter()?
            .map(|item| text(&item?))
            .collect::<Result<_, _>>()?;
        return Ok(items.join(","));
    }
    if let Ok(b) = value.cast::<PyBool>() {
        return Ok(if b.is_true() { "true" } else { "false" }.into());
    }
    Ok(value.str()?.to_cow()?.into_owned())
}
