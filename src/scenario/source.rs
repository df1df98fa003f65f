//! A scenario file's text, parsed, with errors that name the file, line, column and field.

use std::fmt::Display;
use std::ops::Range;
use std::path::{Path, PathBuf};

use anyhow::anyhow;

use super::scenario_toml::ScenarioFile;
use super::text_overrides::{SET_MARK, apply_override};

/// A scenario file as read from disk.
#[derive(Clone, Debug)]
pub struct ScenarioSource {
    /// Where it was read from.
    pub path: PathBuf,
    /// Its text.
    pub text: String,
}

impl ScenarioSource {
    /// Reads `path`.
    pub fn read(path: &Path) -> anyhow::Result<Self> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| anyhow!("{}: cannot read the file: {e}", path.display()))?;
        Ok(Self {
            path: path.to_path_buf(),
            text,
        })
    }

    /// Reads `path` and applies each `--set KEY=VALUE` of `overrides` to its text, in order.
    pub fn read_with(path: &Path, overrides: &[String]) -> anyhow::Result<Self> {
        let mut source = Self::read(path)?;
        for item in overrides {
            source.text = apply_override(&source.text, item)?;
        }
        Ok(source)
    }

    /// Parses the text as a scenario; unknown keys and out-of-range values are errors at
    /// their place. A sweep file is refused with the command that runs it.
    pub fn parse(&self) -> anyhow::Result<ScenarioFile> {
        self.refuse_calibration()?;
        if self.has_table("grid") {
            return Err(anyhow!(
                "{}: this is a sweep file (it has a [grid]): run it with `testrig sweep {} --out DIR`",
                self.path.display(),
                self.path.display()
            ));
        }
        self.parse_as()
    }

    /// Parses the text as a sweep file. A scenario is refused with the command that runs it.
    pub fn parse_sweep<T: serde::de::DeserializeOwned>(&self) -> anyhow::Result<T> {
        self.refuse_calibration()?;
        if !self.has_table("grid") && ["schedule", "survey"].iter().any(|t| self.has_table(t)) {
            return Err(anyhow!(
                "{}: this is a scenario file (it has a [schedule] or [survey], no [grid]): run it with `testrig run {} --out DIR`",
                self.path.display(),
                self.path.display()
            ));
        }
        self.parse_as()
    }

    /// Parses the text as a rig file (`[[body]]`, `[[shaft]]`, `[[mesh]]` …); a scenario or
    /// a sweep is refused naming what it is.
    pub fn parse_rig_file<T: serde::de::DeserializeOwned>(&self) -> anyhow::Result<T> {
        if ["grid", "schedule", "survey"]
            .iter()
            .any(|t| self.has_table(t))
        {
            return Err(anyhow!(
                "{}: this is a scenario or sweep file, not a rig file (a rig file has [[body]], [[shaft]] and [[mesh]] tables; docs/rig-files.md)",
                self.path.display()
            ));
        }
        self.parse_as()
    }

    /// Parses the text as a calibration file. A sweep or a scenario is refused with the
    /// command that runs it.
    pub fn parse_calibration<T: serde::de::DeserializeOwned>(&self) -> anyhow::Result<T> {
        let (command, kind) = if self.has_table("grid") {
            ("sweep", "a sweep file (it has a [grid])")
        } else if ["schedule", "survey"].iter().any(|t| self.has_table(t)) {
            ("run", "a scenario file (it has a [schedule] or [survey])")
        } else {
            return self.parse_as();
        };
        Err(anyhow!(
            "{}: this is {kind}: run it with `testrig {command} {} --out DIR`",
            self.path.display(),
            self.path.display()
        ))
    }

    /// A calibration file (a top-level `campaign`) given to `run` or `sweep`.
    fn refuse_calibration(&self) -> anyhow::Result<()> {
        let is_calibration = toml::from_str::<toml::Table>(&self.text)
            .is_ok_and(|table| table.get("campaign").is_some_and(toml::Value::is_str));
        if is_calibration {
            return Err(anyhow!(
                "{}: this is a calibration file (it names a campaign): run it with `testrig calibrate {} --out DIR`",
                self.path.display(),
                self.path.display()
            ));
        }
        Ok(())
    }

    /// Whether the text, read as TOML, has the top-level table `name`.
    fn has_table(&self, name: &str) -> bool {
        toml::from_str::<toml::Table>(&self.text)
            .is_ok_and(|table| table.get(name).is_some_and(toml::Value::is_table))
    }

    /// Parses the text as any file of this TOML family (a scenario, a sweep).
    fn parse_as<T: serde::de::DeserializeOwned>(&self) -> anyhow::Result<T> {
        toml::from_str(&self.text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            let message = e.message().trim().to_string();
            if message.starts_with("missing field") && span.start == 0 && !self.text.is_empty() {
                // The whole document: a top-level key is missing, not one of the first line.
                return anyhow!(
                    "{}:1:1: top level: {message} (a key before the first [table])",
                    self.path.display()
                );
            }
            self.error(span, &self.key_at(e.span()), message)
        })
    }

    /// An error at `span` of the text about `field`: `FILE:LINE:COLUMN: field: message`.
    /// A span of 0..0 (a value the file left out, or a table as a whole) names no line.
    /// An error on a line written by `--set` names the `--set` instead of the line.
    pub fn error(&self, span: Range<usize>, field: &str, message: impl Display) -> anyhow::Error {
        if span == (0..0) {
            return anyhow!("{}: {field}: {message}", self.path.display());
        }
        if let Some(item) = self.set_item_at(span.start) {
            let message = message.to_string();
            // An unknown key may have been meant as a rig parameter: name the nearest.
            let hint = match message
                .strip_prefix("unknown field `")
                .and_then(|rest| rest.split('`').next())
            {
                Some(key) => format!(
                    "; or a rig parameter by its bare name{} (`testrig params` lists them)",
                    rig::nearest::did_you_mean(key, rig_parameter_names())
                ),
                None => String::new(),
            };
            return anyhow!(
                "--set {item} (on {}): {field}: {message}{hint}",
                self.path.display()
            );
        }
        let (line, column) = self.line_column(span.start);
        anyhow!(
            "{}:{line}:{column}: {field}: {message}",
            self.path.display()
        )
    }

    /// One-based line and column of byte `offset`.
    pub fn line_column(&self, offset: usize) -> (usize, usize) {
        let before = &self.text[..offset.min(self.text.len())];
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |s| s.chars().count()) + 1;
        (line, column)
    }

    /// The `--set` item that wrote the line holding byte `offset`, if one did.
    fn set_item_at(&self, offset: usize) -> Option<&str> {
        let start = self.text[..offset.min(self.text.len())]
            .rfind('\n')
            .map_or(0, |i| i + 1);
        let line = self.text[start..].lines().next()?;
        line.rsplit_once(SET_MARK).map(|(_, item)| item)
    }

    /// The key written on the line of `span` (for parse errors, which carry no field name).
    fn key_at(&self, span: Option<Range<usize>>) -> String {
        let Some(span) = span else {
            return "file".into();
        };
        let start = self.text[..span.start.min(self.text.len())]
            .rfind('\n')
            .map_or(0, |i| i + 1);
        let line = self.text[start..].lines().next().unwrap_or("");
        match line.split_once('=') {
            Some((key, _)) => key.trim().to_string(),
            None => line.trim().to_string(),
        }
    }
}

/// Every rig parameter a bare `--set NAME=VALUE` reaches: stored, then derived.
fn rig_parameter_names() -> Vec<&'static str> {
    rig::PARAM_SPECS
        .iter()
        .chain(rig::DERIVED_SPECS)
        .map(|s| s.name)
        .collect()
}
