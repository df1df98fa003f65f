//! `testrig merge`: the finished cases of several sweep folders as one table and its plots.

use testrig::sweep::assemble;

use crate::cli::MergeArgs;

pub fn run(args: &MergeArgs) -> anyhow::Result<()> {
    let assembled = assemble(&args.dirs, &args.out)?;
    println!(
        "merged {} folders: {} files in {}",
        args.dirs.len(),
        assembled.files.len(),
        args.out.display()
    );
    if !assembled.missing.is_empty() {
        let shown: Vec<String> = assembled
            .missing
            .iter()
            .take(12)
            .map(usize::to_string)
            .collect();
        let more = assembled.missing.len().saturating_sub(shown.len());
        eprintln!(
            "warning: {} cases of the grid are in none of the folders (a shard not given, or not finished; `testrig sweep --shard K/N --resume` completes one): {}{}",
            assembled.missing.len(),
            shown.join(", "),
            if more > 0 {
                format!(" and {more} more")
            } else {
                String::new()
            }
        );
    }
    Ok(())
}
