//! Records where this build puts its artefacts (`<target>/<profile>`, from `OUT_DIR`), so
//! that `testrig fmu` finds the FMU's shared library built there also when the binary
//! was copied elsewhere: `cargo install --path .` builds in the workspace's `target/` and
//! installs only the binary.

fn main() {
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR for build scripts");
    // OUT_DIR is <target>/<profile>/build/testrig-<hash>/out.
    let profile_dir = std::path::Path::new(&out_dir)
        .ancestors()
        .nth(3)
        .expect("OUT_DIR lies three folders below the profile's");
    println!(
        "cargo:rustc-env=TESTRIG_BUILD_PROFILE_DIR={}",
        profile_dir.display()
    );
    println!("cargo:rerun-if-changed=build.rs");
}
