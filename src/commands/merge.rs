//! `testrig merge`: the finished cases of several sweep folders as one table and its plots.

use anyhow::bail;
use testrig::sweep::{assemble, missing_cases};

use crate::cli::MergeArgs;

pub fn run(args: &MergeArgs) -> anyhow::Result<()> {
    if !args.partial {
        let missing = missing_cases(&args.dirs)?;
        if !missing.is_empty() {
            bail!(
                "{} cases of the grid are in none of the folders (a shard not given, or not finished; `testrig sweep --shard K/N --resume` completes one): {}; nothing merged (--partial merges what there is)",
                missing.len(),
                listed(&missing)
            );
        }
    }
    let assembled = assemble(&args.dirs, &args.out)?;
    println!(
        "merged {} folders: {} files in {}",
        args.dirs.len(),
        assembled.files.len(),
        args.out.display()
    );
    if !assembled.missing.is_empty() {
        eprintln!(
            "warning: {} cases of the grid are in none of the folders (merged with --partial): {}",
            assembled.missing.len(),
            listed(&assembled.missing)
        );
    }
    Ok(())
}

/// The first dozen of `indices`, and how many more.
fn listed(indices: &[usize]) -> String {
    let shown: Vec<String> = indices.iter().take(12).map(usize::to_string).collect();
    match indices.len().saturating_sub(shown.len()) {
        0 => shown.join(", "),
        more => format!("{} and {more} more", shown.join(", ")),
    }
}
