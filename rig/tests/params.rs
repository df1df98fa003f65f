//! Parameters by name, validation and bad input.

mod support;

use rig::{PARAM_SPECS, Plant, PlantConfig, RigError, Schedule, param_spec, preset, set_param};

#[test]
fn every_parameter_reads_back_what_was_set() {
    let base = support::thesis();
    for spec in PARAM_SPECS {
        let mut p = base.clone();
        let value = spec.value(&base);
        set_param(&mut p, spec.name, &value).unwrap_or_else(|e| panic!("{}: {e}", spec.name));
        assert_eq!(p, base, "{}", spec.name);
        assert!(!spec.unit.is_empty() && !spec.meaning.is_empty());
    }
}

#[test]
fn overrides_change_the_named_field_only() {
    let mut p = support::thesis();
    set_param(&mut p, "teeth", "31").expect("valid");
    set_param(&mut p, "contact_law", "no-pull").expect("valid");
    set_param(&mut p, "k23_mesh_nm_per_rad", "2e6").expect("valid");
    assert_eq!(p.teeth, 31);
    assert_eq!(p.contact_law, rig::ContactLaw::NoPull);
    assert_eq!(p.k23_mesh_nm_per_rad, 2e6);
}

#[test]
fn bad_values_are_refused_with_the_name() {
    let mut p = support::thesis();
    let before = p.clone();
    for (name, value) in [
        ("j1_motor_kgm2", "-1"),
        ("k12_input_shaft_nm_per_rad", "NaN"),
        ("teeth", "2.5"),
        ("contact_law", "sticky"),
        ("backlash_variation_c1", "1.5"),
    ] {
        let err = set_param(&mut p, name, value).expect_err(name);
        assert!(err.to_string().contains(name), "{err}");
        assert_eq!(p, before, "a refused value must leave the set unchanged");
    }
    assert!(matches!(
        param_spec("j9"),
        Err(RigError::UnknownParameter { .. })
    ));
    assert!(matches!(
        preset("basmaji-1984"),
        Err(RigError::UnknownPreset { .. })
    ));
}

#[test]
fn bad_schedules_and_options_are_refused() {
    let p = support::thesis();
    let negative = Plant::new(
        p.clone(),
        Schedule::constant(-10.0, 0.0),
        PlantConfig::default(),
    );
    assert!(matches!(negative, Err(RigError::Schedule(_))));
    let slow = PlantConfig {
        output_rate_hz: 1.0,
        ..PlantConfig::default()
    };
    assert!(matches!(
        Plant::new(p, Schedule::constant(600.0, 0.0), slow),
        Err(RigError::InvalidOption { .. })
    ));
}

#[test]
fn a_blow_up_is_reported_with_time_and_state() {
    let mut p = support::thesis();
    // Negative damping feeds energy into the intermediate shaft mode; without backlash no
    // impact limits it.
    p.c34_intermediate_shaft_nms_per_rad = -5.0;
    p.centre_distance_shift_m = 0.0;
    p.tooth_shifting = false;
    p.backlash_variation_c1 = 0.0;
    let mut plant = support::plant(p, Schedule::constant(600.0, 2.712), 5_120.0);
    let mut state = plant.relative_state();
    state[5 + 3] = 0.01;
    plant.set_relative_state(state, rig::MeshMode::Drive);
    let err = plant
        .skip(5_120 * 120)
        .expect_err("the motion must grow without bound");
    match err {
        RigError::BlowUp { t_s, state, .. } => {
            assert!(t_s > 0.0 && t_s < 120.0);
            assert_eq!(state.len(), 10);
        }
        other => panic!("{other}"),
    }
}

#[test]
fn values_set_by_kind_are_checked_against_the_parameter_without_text() {
    use rig::{ParamValue, set_param_value};
    let mut p = preset("basmaji-1983").expect("preset");
    set_param_value(&mut p, "teeth", ParamValue::Number(31.0)).expect("a whole number");
    assert_eq!(p.teeth, 31);
    assert!(set_param_value(&mut p, "teeth", ParamValue::Number(31.5)).is_err());
    assert!(set_param_value(&mut p, "teeth", ParamValue::Switch(true)).is_err());
    set_param_value(&mut p, "tooth_shifting", ParamValue::Switch(false)).expect("a switch");
    assert!(!p.tooth_shifting);
    set_param_value(&mut p, "contact_law", ParamValue::Text("no-pull")).expect("a name");
    assert!(
        set_param_value(
            &mut p,
            "k12_input_shaft_nm_per_rad",
            ParamValue::Number(f64::NAN)
        )
        .is_err()
    );
    // A number is kept to the bit.
    let x = 0.1 + 0.2;
    set_param_value(&mut p, "brake_drag_nm", ParamValue::Number(x)).expect("a number");
    assert_eq!(p.brake_drag_nm.to_bits(), x.to_bits());
    set_param_value(&mut p, "backlash_mm", ParamValue::Number(0.73)).expect("backlash");
    assert!((rig::GearGeometry::of(&p).circular_backlash_m - 0.73e-3).abs() < 1e-12);
    assert!(set_param_value(&mut p, "backlash_mm", ParamValue::Number(-1.0)).is_err());
}
