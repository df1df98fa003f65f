//! The planar model of a planetary stage against its published reference: J. Lin and
//! R. G. Parker, "Analytical characterization of the unique properties of planetary gear
//! free vibration", J. Vib. Acoust. 121(3), 1999. The shipped rig file
//! `scenarios/rigs/lin-parker-1999.toml` is their Table 1's example stage; its natural
//! frequencies at zero speed, with 3, 4 and 5 equally spaced planets, are held against
//! their Table 2, each within 0.1 %, and the modes' kinds against the structure the paper
//! proves: rotational modes (the central members only turn), degenerate pairs of
//! translational modes (they only translate) and, from 4 planets on, planet modes (the
//! central members still).

use std::path::PathBuf;

use rig::{ModeKind, RigTopology};
use testrig::scenario::{ScenarioSource, rig_topology};

/// Table 2 of Lin & Parker (1999), Hz: the rotational modes (0 Hz, the stage turning
/// freely, included), each translational frequency (a degenerate pair) and each planet
/// mode's frequency (N − 3 modes each).
struct Table2 {
    planets: u32,
    rotational: &'static [f64],
    translational: &'static [f64],
    planet: &'static [f64],
}

const TABLE_2: [Table2; 3] = [
    Table2 {
        planets: 3,
        rotational: &[0.0, 1475.7, 1930.3, 2658.3, 7462.8, 11775.3],
        translational: &[743.2, 1102.4, 1896.0, 2276.4, 6986.3, 9647.9],
        planet: &[],
    },
    Table2 {
        planets: 4,
        rotational: &[0.0, 1536.6, 1970.6, 2625.7, 7773.6, 13071.1],
        translational: &[727.0, 1091.0, 1892.8, 2342.5, 7189.9, 10437.6],
        planet: &[1808.2, 5963.8, 6981.7],
    },
    Table2 {
        planets: 5,
        rotational: &[0.0, 1567.4, 2006.1, 2614.8, 8065.4, 14253.1],
        translational: &[710.0, 1072.0, 1888.1, 2425.3, 7382.4, 11172.3],
        planet: &[1808.2, 5963.8, 6981.7],
    },
];

/// The shipped file with `planets` planets.
fn stage_with(planets: u32) -> RigTopology {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/rigs/lin-parker-1999.toml");
    let mut source = ScenarioSource::read(&path).expect("shipped file");
    assert!(source.text.contains("\nplanets = 3\n"));
    source.text = source
        .text
        .replace("\nplanets = 3\n", &format!("\nplanets = {planets}\n"));
    rig_topology(&source).expect("Lin & Parker's stage reads")
}

/// Each published frequency (Hz) with its kind, as many times as it occurs, ascending;
/// the rigid-body mode (0 Hz) left out, as `modes` leaves it out.
fn published(t: &Table2) -> Vec<(f64, ModeKind)> {
    let planet_modes = t.planets as usize - 3;
    let mut all: Vec<(f64, ModeKind)> = t.rotational[1..]
        .iter()
        .map(|&f| (f, ModeKind::Rotational))
        .chain(
            t.translational
                .iter()
                .flat_map(|&f| [(f, ModeKind::Translational); 2]),
        )
        .chain(
            t.planet
                .iter()
                .flat_map(|&f| std::iter::repeat_n((f, ModeKind::Planet), planet_modes)),
        )
        .collect();
    all.sort_by(|a, b| a.0.total_cmp(&b.0));
    all
}

#[test]
fn natural_frequencies_match_lin_parker_1999_table_2_for_3_4_and_5_planets() {
    for table in &TABLE_2 {
        let rig = stage_with(table.planets);
        let modes = rig.natural_modes();
        let expected = published(table);
        assert_eq!(
            modes.len(),
            expected.len(),
            "{} planets: 3(N + 3) − 1 flexible modes",
            table.planets
        );
        for (mode, &(hz, _)) in modes.iter().zip(&expected) {
            let error = (mode.frequency_hz - hz).abs() / hz;
            assert!(
                error < 1e-3,
                "{} planets: {:.2} Hz against Table 2's {hz} Hz ({:.3} %)",
                table.planets,
                mode.frequency_hz,
                error * 100.0
            );
        }
    }
}

#[test]
fn mode_kinds_are_lin_and_parkers_rotational_translational_and_planet_modes() {
    for table in &TABLE_2 {
        let rig = stage_with(table.planets);
        let kinds = rig.mode_kinds(&rig.natural_modes());
        let expected: Vec<ModeKind> = published(table).into_iter().map(|(_, k)| k).collect();
        assert_eq!(kinds, expected, "{} planets", table.planets);
    }
}
