//! The FMU (`testrig fmu`, `docs/fmu.md`) through its C functions, as an importer calls
//! them: outputs equal `simulate --rig --approach rest` of the same point and do not
//! depend on the communication step, nor on inputs set again before every step to the
//! values they have; a set point changed between steps is the
//! schedule's step at that instant; a saved state repeats the same future; a steady
//! point carries the brake's load through the shafts; bad calls and values are refused
//! with a message, never a crash. The exported file and its importers: `tests/fmu_export.rs`.

mod common;
mod fmu_support;

use common::folder;
use fmu_support::Fmu;
use rig::{NetworkBlock, NetworkPlant, NetworkStart, RigTopology, Schedule, Track};
use testrig::steady_point::{RigPointSpec, run_rig_point};
use testrig::vocabulary::FLAG_NAMES;
use testrig_fmu::ffi::{self, ERROR, OK};
use testrig_fmu::{Causality, SAMPLE_RATE_HZ, variables};
use testrig_fmu::{ffi_state, ffi_values};

fn rig_path() -> String {
    common::rig_file("basmaji-1983")
}

fn rig() -> RigTopology {
    testrig::scenario::read_rig_file(std::path::Path::new(&rig_path())).expect("rig file")
}

/// Runs `fmu` from `from_s` to `to_s` in steps of `h_s`, the outputs after each step.
fn run(fmu: &mut Fmu, from_s: f64, to_s: f64, h_s: f64) -> Vec<(f64, Vec<f64>)> {
    let steps = ((to_s - from_s) / h_s).round() as usize;
    (0..steps)
        .map(|k| {
            let t = from_s + k as f64 * h_s;
            assert_eq!(fmu.step(t, h_s), OK, "{:?}", fmu.messages());
            (t + h_s, fmu.outputs())
        })
        .collect()
}

/// The outputs' names in value-reference order.
fn output_names(rig: &RigTopology) -> Vec<String> {
    variables(rig)
        .into_iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.name)
        .collect()
}

fn started(rig: &RigTopology, dir: &std::path::Path, rpm: f64, load_nm: f64) -> Fmu {
    let mut fmu = Fmu::new(rig, dir, None);
    assert!(!fmu.instance.is_null(), "{:?}", fmu.messages());
    assert_eq!(fmu.set("set_speed_rpm", rpm), OK);
    assert_eq!(fmu.set("load_nm", load_nm), OK);
    fmu.initialize();
    fmu
}

#[test]
fn outputs_equal_simulate_from_rest_whatever_the_communication_step() {
    let rig = rig();
    let dir = folder("fmu-steps");
    let mut fine = started(&rig, dir.path(), 1300.0, 2.712);
    let mut coarse = started(&rig, dir.path(), 1300.0, 2.712);
    let fine_out = run(&mut fine, 0.0, 2.0, 0.001);
    let coarse_out = run(&mut coarse, 0.0, 2.0, 0.01);
    // The reference: `testrig simulate --rig … --approach rest --settle 0 --rate 10000`.
    let spec = RigPointSpec {
        rig: &rig,
        rpm: 1300.0,
        load_nm: 2.712,
        settle_s: 0.0,
        duration_s: 2.5,
        rate_hz: SAMPLE_RATE_HZ,
        approach: rig::Approach::Rest,
    };
    let mut reference: Vec<Vec<f64>> = Vec::new();
    run_rig_point(
        &spec,
        FLAG_NAMES,
        || Ok(()),
        |block| {
            let columns = rig::columns(&rig, block);
            for i in 0..block.len() {
                reference.push(columns.iter().skip(1).map(|c| c[i]).collect());
            }
            Ok(())
        },
    )
    .expect("simulate");
    let names = output_names(&rig);
    let mut compared = 0;
    for (t, coarse_values) in &coarse_out {
        let k = (t / 0.001).round() as usize - 1;
        assert_eq!(
            fine_out[k].1, *coarse_values,
            "1 ms and 10 ms steps at {t} s"
        );
        let row = &reference[(t * SAMPLE_RATE_HZ).round() as usize];
        for (j, want) in row.iter().enumerate() {
            let got = coarse_values[j];
            let scale = want.abs().max(1e-6);
            assert!(
                (got - want).abs() <= 1e-9 * scale,
                "{} at {t} s: FMU {got}, simulate {want}",
                names[j]
            );
        }
        compared += 1;
    }
    assert_eq!(compared, 200);
    let impacts = coarse_out.last().expect("steps").1[names.len() - 1];
    assert!(
        impacts > 10.0,
        "the run-up rattles: {impacts} impacts in 2 s"
    );
}

/// Runs `fmu` from 0 to `to_s` in steps of `h_s` as a master with connected inputs does:
/// every input set before every step (now and then an ulp off, as interpolation rounds),
/// the speed stepping to `later_rpm` at `change_s`.
fn run_setting_inputs(
    fmu: &mut Fmu,
    to_s: f64,
    h_s: f64,
    change_s: f64,
    later_rpm: f64,
) -> Vec<(f64, Vec<f64>)> {
    let steps = (to_s / h_s).round() as usize;
    (0..steps)
        .map(|k| {
            let t = k as f64 * h_s;
            let rpm = if t + 1e-9 >= change_s {
                later_rpm
            } else {
                1300.0
            };
            // A master interpolating between equal rows lands an ulp off now and then
            // (FMPy's w0 v0 + (1 - w0) v1): the same set point still.
            let rpm = if k % 3 == 1 {
                f64::from_bits(rpm.to_bits() + 1)
            } else {
                rpm
            };
            assert_eq!(fmu.set("set_speed_rpm", rpm), OK);
            assert_eq!(fmu.set("load_nm", 2.712), OK);
            assert_eq!(fmu.step(t, h_s), OK, "{:?}", fmu.messages());
            (t + h_s, fmu.outputs())
        })
        .collect()
}

#[test]
fn inputs_set_before_every_step_give_the_same_motion_whatever_the_step() {
    let rig = rig();
    let dir = folder("fmu-inputs-every-step");
    let names = output_names(&rig);
    // Constant inputs set every step, then a speed stepped at 1 s, a shared point.
    for later_rpm in [1300.0, 1000.0] {
        let mut fine = started(&rig, dir.path(), 1300.0, 2.712);
        let mut coarse = started(&rig, dir.path(), 1300.0, 2.712);
        let fine_out = run_setting_inputs(&mut fine, 2.0, 0.001, 1.0, later_rpm);
        let coarse_out = run_setting_inputs(&mut coarse, 2.0, 0.01, 1.0, later_rpm);
        let mut held = started(&rig, dir.path(), 1300.0, 2.712);
        let held_out = run(&mut held, 0.0, 1.0, 0.01);
        for (t, coarse_values) in &coarse_out {
            let k = (t / 0.001).round() as usize - 1;
            for (j, (got, want)) in coarse_values.iter().zip(&fine_out[k].1).enumerate() {
                assert!(
                    (got - want).abs() <= 1e-9 * want.abs().max(1e-6),
                    "{} at {t} s ({later_rpm} rev/min after 1 s): 10 ms steps {got}, 1 ms {want}",
                    names[j]
                );
            }
        }
        // Setting an input to the value it has is no change at all: to the bit.
        for (k, (_, values)) in held_out.iter().enumerate() {
            assert_eq!(
                *values, coarse_out[k].1,
                "inputs left alone vs set again, step {k}"
            );
        }
    }
}

#[test]
fn a_set_point_changed_between_steps_is_the_schedules_step() {
    let rig = rig();
    let dir = folder("fmu-input-step");
    let mut fmu = started(&rig, dir.path(), 600.0, 1.0);
    run(&mut fmu, 0.0, 2.0, 0.01);
    assert_eq!(fmu.set("set_speed_rpm", 900.0), OK);
    assert_eq!(fmu.set("load_nm", 2.0), OK);
    let last = run(&mut fmu, 2.0, 3.0, 0.01).pop().expect("steps").1;
    let schedule = Schedule {
        speed_rpm: Track::hold(600.0).step_to(2.0, 900.0),
        load_nm: Track::hold(1.0).step_to(2.0, 2.0),
        oscillating_load_nm: Track::hold(0.0),
        oscillating_load_hz: Track::hold(0.0),
    };
    let mut plant =
        NetworkPlant::new(&rig, schedule, SAMPLE_RATE_HZ, NetworkStart::Rest).expect("plant");
    let mut block = NetworkBlock::new(&rig);
    plant.run(30_000, &mut block).expect("run");
    block.clear();
    plant.sample_now(&mut block);
    let want: Vec<f64> = rig::columns(&rig, &block)
        .iter()
        .skip(1)
        .map(|c| c[0])
        .collect();
    for (got, want) in last.iter().zip(&want) {
        assert!(
            (got - want).abs() <= 1e-9 * want.abs().max(1e-6),
            "{got} vs {want}"
        );
    }
}

#[test]
fn a_saved_state_repeats_the_same_future_and_a_reset_the_same_run() {
    let rig = rig();
    let dir = folder("fmu-state");
    let mut fmu = started(&rig, dir.path(), 1300.0, 2.712);
    let to_one = run(&mut fmu, 0.0, 1.0, 0.01);
    let mut state = std::ptr::null_mut();
    // SAFETY: a live instance and a writable place.
    assert_eq!(
        unsafe { ffi_state::fmi3GetFMUState(fmu.instance, &mut state) },
        OK
    );
    let first = run(&mut fmu, 1.0, 1.5, 0.01);
    // SAFETY: the state just saved.
    assert_eq!(
        unsafe { ffi_state::fmi3SetFMUState(fmu.instance, state) },
        OK
    );
    assert!((fmu.float("time") - 1.0).abs() < 1e-12);
    let again = run(&mut fmu, 1.0, 1.5, 0.01);
    assert_eq!(first, again);
    // SAFETY: the state, freed once.
    unsafe {
        assert_eq!(ffi_state::fmi3FreeFMUState(fmu.instance, &mut state), OK);
    }
    assert!(state.is_null());
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(ffi::fmi3Terminate(fmu.instance), OK);
        assert_eq!(ffi::fmi3Reset(fmu.instance), OK);
    }
    assert_eq!(fmu.float("set_speed_rpm"), 0.0, "reset: start values again");
    assert_eq!(fmu.set("set_speed_rpm", 1300.0), OK);
    assert_eq!(fmu.set("load_nm", 2.712), OK);
    fmu.initialize();
    assert_eq!(
        run(&mut fmu, 0.0, 1.0, 0.01),
        to_one,
        "after fmi3Reset, the same run"
    );
}

#[test]
fn at_a_steady_point_the_shafts_carry_the_brakes_load_at_the_set_speed() {
    let rig = rig();
    let dir = folder("fmu-steady");
    let mut fmu = started(&rig, dir.path(), 400.0, 4.0);
    let out = run(&mut fmu, 0.0, 60.0, 0.1);
    let names = output_names(&rig);
    let at = |name: &str| names.iter().position(|n| n == name).expect("name");
    let tail = &out[out.len() - 100..];
    let mean = |j: usize| tail.iter().map(|(_, v)| v[j]).sum::<f64>() / tail.len() as f64;
    let speed = mean(at("speed_brake_rpm"));
    assert!((speed - 400.0).abs() < 0.5, "brake at {speed} rev/min");
    let torque = mean(at("torque_final_nm"));
    assert!(
        (torque - 4.0).abs() < 0.02,
        "final shaft carries {torque} N m"
    );
}

#[test]
fn bad_calls_and_values_are_refused_with_a_message() {
    let rig = rig();
    let dir = folder("fmu-refusals");
    let mut fmu = Fmu::new(&rig, dir.path(), None);
    let status = fmu.step(0.0, 0.01);
    assert!(fmu.refused(
        status,
        "fmi3DoStep is not allowed in the Instantiated state"
    ));
    let speed = fmu.vr("speed_motor_rpm");
    let status = fmu.get(speed, testrig_fmu::Kind::Float64).unwrap_err();
    assert!(fmu.refused(status, "is known from fmi3EnterInitializationMode on"));
    let status = fmu.set("set_speed_rpm", f64::NAN);
    assert!(fmu.refused(status, "set_speed_rpm = NaN: out of range"));
    let status = fmu.set("set_speed_rpm", 5000.0);
    assert!(fmu.refused(status, "above speed_ceiling_rpm = 3000"));
    let status = fmu.set("load_nm", 9.0);
    assert!(fmu.refused(status, "load_nm = 9: out of range (min 0, max 7.12"));
    let status = fmu.set("load_nm", -1.0);
    assert!(fmu.refused(status, "load_nm = -1: out of range"));
    let status = fmu.set("speed_motor_rpm", 1.0);
    assert!(fmu.refused(status, "is an output: it cannot be set"));
    assert_eq!(
        fmu.float("set_speed_rpm"),
        0.0,
        "a refused value is not taken"
    );
    fmu.set("set_speed_rpm", 1000.0);
    fmu.initialize();
    let status = fmu.set("body.motor.inertia_kgm2", 1.0);
    assert!(fmu.refused(status, "is not allowed in the Step state"));
    let status = fmu.step(0.0, 0.000_15);
    assert!(fmu.refused(status, "whole number of the FMU's 0.0001 s samples"));
    let status = fmu.step(0.5, 0.01);
    assert!(fmu.refused(status, "the FMU is at 0 s"));
    assert_eq!(fmu.step(0.0, 0.01), OK, "still usable after refusals");
    let bad = 100_000;
    // SAFETY: one value reference, one place.
    let status = unsafe { ffi_values::fmi3GetFloat64(fmu.instance, &bad, 1, &mut 0.0, 1) };
    assert!(fmu.refused(status, "no variable has value reference 100000"));
    // SAFETY: null arrays with counts, a null instance: refused, not dereferenced.
    unsafe {
        let status =
            ffi_values::fmi3GetFloat64(fmu.instance, std::ptr::null(), 2, std::ptr::null_mut(), 2);
        assert!(fmu.refused(status, "a null array of 2 values"));
        assert_eq!(
            ffi::fmi3DoStep(
                std::ptr::null_mut(),
                0.0,
                0.01,
                true,
                std::ptr::null_mut(),
                std::ptr::null_mut(),
                std::ptr::null_mut(),
                std::ptr::null_mut()
            ),
            ERROR
        );
    }
    // SAFETY: a live instance; event mode is not offered.
    let status = unsafe { testrig_fmu::ffi_unoffered::fmi3EnterEventMode(fmu.instance) };
    assert!(fmu.refused(status, "not offered"));
}

#[test]
fn a_parameter_the_rig_cannot_take_is_refused_when_initialization_ends() {
    let rig = rig();
    let dir = folder("fmu-parameter");
    let mut fmu = Fmu::new(&rig, dir.path(), None);
    assert_eq!(
        fmu.set("mesh.gears.backlash_mm", 1e3),
        OK,
        "checked with the whole rig later"
    );
    // SAFETY: a live instance.
    let status = unsafe {
        assert_eq!(
            ffi::fmi3EnterInitializationMode(fmu.instance, false, 0.0, 0.0, false, 0.0),
            OK
        );
        ffi::fmi3ExitInitializationMode(fmu.instance)
    };
    assert!(fmu.refused(status, "backlash"), "{:?}", fmu.messages());
    assert_eq!(fmu.set("mesh.gears.backlash_mm", 0.5), OK);
    // SAFETY: a live instance.
    assert_eq!(unsafe { ffi::fmi3ExitInitializationMode(fmu.instance) }, OK);
    assert_eq!(fmu.step(0.0, 0.01), OK);
}

#[test]
fn a_wrong_token_or_missing_resources_give_no_instance_and_say_why() {
    let rig = rig();
    let dir = folder("fmu-token");
    let fmu = Fmu::new(&rig, dir.path(), Some("{not-this-one}"));
    assert!(fmu.instance.is_null());
    assert!(
        fmu.messages()
            .iter()
            .any(|m| m.contains("the model description and resources/rig.json differ")),
        "{:?}",
        fmu.messages()
    );
}
