//! `testrig merge`: the finished cases of several sweep folders as one table and its plots.

use testrig::sweep::assemble;

use crate::cli::MergeArgs;

pub fn run(args: &MergeArgs) -> anyhow::Result<()> {
    let files = assemble(&args.dirs, &args.out)?;
    println!(
        "merged {} folders: {} files in {}",
        args.dirs.len(),
        files.len(),
        args.out.display()
    );
    Ok(())
}
