//! File descriptors the panel's server may hold, so that a flood of connections never
//! takes the ones the run needs for its recordings.

/// Descriptors kept for the run (its recordings, spectra, plots) and the process.
const KEPT_FOR_THE_RUN: u64 = 128;

/// Raises the process's soft limit on open files to its hard limit (as servers do), and
/// returns how many descriptors the server may use for connections: the limit less those
/// kept for the run.
pub fn descriptors_for_connections() -> usize {
    let mut limit = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: getrlimit and setrlimit read and write the one struct passed; no other
    // memory is touched.
    let soft = unsafe {
        if libc::getrlimit(libc::RLIMIT_NOFILE, &mut limit) != 0 {
            return 256;
        }
        let raised = libc::rlimit {
            rlim_cur: limit.rlim_max,
            rlim_max: limit.rlim_max,
        };
        if libc::setrlimit(libc::RLIMIT_NOFILE, &raised) == 0 {
            limit.rlim_max
        } else {
            limit.rlim_cur
        }
    };
    usize::try_from(soft.saturating_sub(KEPT_FOR_THE_RUN)).unwrap_or(usize::MAX)
}
