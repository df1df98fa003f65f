//! The FMU as `testrig fmu` exports it: the zip holds the description, the binary, the rig
//! and the docs, the same rig gives the same bytes, a copy of the binary installed
//! elsewhere finds its library; FMPy and a second importer (the FMU Manipulation
//! Toolbox's checker and container runtime) judge it in `tests/fmu/importers.py`
//! (`fmu_importers_agree`).

mod common;

use std::io::Read;

use common::{folder, testrig};

#[test]
fn an_installed_binary_elsewhere_finds_the_library_it_was_built_with() {
    // `cargo install --path .` builds in the workspace's target/release and copies only
    // the binary to ~/.cargo/bin: a copy in another folder must still export.
    let dir = folder("fmu-installed");
    let installed = dir.path().join("testrig");
    std::fs::copy(env!("CARGO_BIN_EXE_testrig"), &installed).expect("copy the binary");
    let fmu = dir.path().join("rig.fmu");
    let out = std::process::Command::new(&installed)
        .args(["fmu", "--rig", &common::rig_file("basmaji-1983"), "--out"])
        .arg(&fmu)
        .env_remove("TESTRIG_FMU_LIBRARY")
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::metadata(&fmu).expect("the FMU").len() > 100_000);
}

#[test]
fn the_export_holds_description_binary_rig_and_docs_and_is_reproducible() {
    let dir = folder("fmu-export");
    let paths = [dir.path().join("a.fmu"), dir.path().join("b.fmu")];
    for path in &paths {
        let out = testrig(&[
            "fmu",
            "--rig",
            &common::rig_file("basmaji-1983"),
            "--set",
            "mesh.gears.backlash_variation=0.2",
            "--out",
            path.to_str().expect("path"),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let bytes = std::fs::read(&paths[0]).expect("fmu");
    assert_eq!(
        bytes,
        std::fs::read(&paths[1]).expect("fmu"),
        "same rig, same bytes"
    );
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(bytes)).expect("zip");
    let mut names: Vec<String> = zip.file_names().map(str::to_owned).collect();
    names.sort();
    assert_eq!(
        names,
        [
            "binaries/x86_64-linux/testrig_basmaji_1983.so",
            "documentation/index.html",
            "modelDescription.xml",
            "resources/rig.json",
        ]
    );
    let mut xml = String::new();
    zip.by_name("modelDescription.xml")
        .expect("xml")
        .read_to_string(&mut xml)
        .expect("text");
    assert!(xml.contains(r#"name="mesh.gears.backlash_variation""#));
    assert!(
        xml.contains(r#"start="0.2""#),
        "--set gives the start value"
    );
    let rig =
        testrig::scenario::read_rig_file(std::path::Path::new(&common::rig_file("basmaji-1983")))
            .expect("rig file");
    for name in rig::column_names(&rig).iter().skip(1) {
        assert!(xml.contains(&format!(r#"name="{name}""#)), "{name}");
    }
    for name in ["basmaji-1983", "basmaji-1983-calibrated"] {
        let preset = dir.path().join(format!("{name}-preset.fmu"));
        let plain = dir.path().join(format!("{name}-plain.fmu"));
        for (args, path) in [
            (["--preset", name], &preset),
            (["--rig", common::rig_file(name).as_str()], &plain),
        ] {
            let out = testrig(
                &[
                    &["fmu"],
                    &args[..],
                    &["--out", path.to_str().expect("path")],
                ]
                .concat(),
            );
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
        assert_eq!(
            std::fs::read(&preset).expect("fmu"),
            std::fs::read(&plain).expect("fmu"),
            "--preset {name} is its rig file"
        );
    }
    let other = testrig(&["fmu", "--preset", "basmaji-1983-rgi", "--out", "x.fmu"]);
    assert!(!other.status.success());
    assert!(
        String::from_utf8_lossy(&other.stderr).contains("did you mean `basmaji-1983-rig`"),
        "{}",
        String::from_utf8_lossy(&other.stderr)
    );
    let bad = testrig(&[
        "fmu",
        "--rig",
        &common::rig_file("basmaji-1983"),
        "--set",
        "mesh.gears.teeth=3",
        "--out",
        "x.fmu",
    ]);
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("mesh.gears.teeth"));
}

#[test]
#[ignore = "needs Python modules (python3 -m pip install -r tests/requirements.txt); run by .ci/run"]
fn fmu_importers_agree() {
    common::run_python_check(
        "fmu/importers.py",
        "fmu-importers",
        &["fmpy", "fmu_manipulation_toolbox", "numpy", "matplotlib"],
    );
}
