//! The oscilloscope's trigger and trace, and the brake drive's coil lag.

use instruments::{Block, BrakeDrive, BrakeDriveSettings, Scope, ScopeSettings, Slope, SweepMode};
use std::f64::consts::PI;

const RATE: f64 = 51_200.0;

fn scope(slope: Slope, mode: SweepMode) -> Scope {
    let settings = ScopeSettings {
        volts_per_div: 0.5,
        seconds_per_div: 0.002,
        trigger_v: 0.25,
        slope,
        mode,
    };
    Scope::new(settings, RATE).expect("valid")
}

fn sine(freq_hz: f64, amplitude: f64, samples: usize, offset: usize) -> Vec<f64> {
    (offset..offset + samples)
        .map(|k| amplitude * (2.0 * PI * freq_hz * k as f64 / RATE).sin())
        .collect()
}

#[test]
fn the_sweep_starts_at_the_trigger_level_on_the_chosen_slope() {
    for slope in [Slope::Rising, Slope::Falling] {
        let mut s = scope(slope, SweepMode::Repeat);
        let input = sine(100.0, 1.0, 20_000, 0);
        let mut through = vec![0.0; input.len()];
        s.process(&input, &mut through);
        assert_eq!(through, input, "the scope passes the stream through");
        let trace = s.trace().expect("a sweep");
        assert_eq!(trace.len(), (10.0 * 0.002 * RATE) as usize);
        // Vertical position in divisions: the level 0.25 V is half a division.
        let (first, second) = (trace[0].1, trace[1].1);
        assert!((first - 0.5).abs() < 0.02, "{first}");
        match slope {
            Slope::Rising => assert!(second > first),
            Slope::Falling => assert!(second < first),
        }
        // Twenty milliseconds show two periods of 100 Hz.
        assert!((trace.last().expect("samples").0 - 0.02).abs() < 1e-4);
    }
}

#[test]
fn single_sweep_holds_the_first_trace_and_the_screen_clips() {
    let mut s = scope(Slope::Rising, SweepMode::Single);
    let mut out = vec![0.0; 10_000];
    s.process(&sine(100.0, 1.0, 10_000, 0), &mut out);
    let first = s.trace().expect("a sweep");
    s.process(&sine(100.0, 5.0, 10_000, 10_000), &mut out);
    assert_eq!(s.trace().expect("held"), first);
    let mut repeat = scope(Slope::Rising, SweepMode::Repeat);
    let mut out = vec![0.0; 20_000];
    repeat.process(&sine(100.0, 5.0, 20_000, 0), &mut out);
    let peak = repeat
        .trace()
        .expect("a sweep")
        .iter()
        .map(|p| p.1)
        .fold(0.0, f64::max);
    assert_eq!(peak, 4.0, "5 V at 0.5 V/div clips at the top of the screen");
}

#[test]
fn the_brake_torque_follows_the_coil_current_through_its_lag() {
    let settings = BrakeDriveSettings {
        ac_amplitude_a: 0.2,
        ac_frequency_hz: 15.0,
        coil_time_constant_s: 0.01,
        torque_per_amp: 2.5,
    };
    let mut drive = BrakeDrive::new(settings, RATE).expect("valid");
    let n = 2 * RATE as usize;
    let mut torque = vec![0.0; n];
    drive.process(&vec![1.0; n], &mut torque);
    // Project the last second on 15 Hz: AC torque amplitude and phase against k/(1 + jωτ).
    let half = n / 2;
    let (mut re, mut im, mut mean) = (0.0, 0.0, 0.0);
    for (k, &t) in torque.iter().enumerate().skip(half) {
        let phase = 2.0 * PI * 15.0 * k as f64 / RATE;
        re += t * phase.sin();
        im += t * phase.cos();
        mean += t;
    }
    let count = (n - half) as f64;
    let (re, im, mean) = (2.0 * re / count, 2.0 * im / count, mean / count);
    let want = drive.response(15.0).expect("linear") * 0.2;
    assert!((mean - 2.5).abs() < 1e-3, "DC torque {mean}");
    assert!(
        (re.hypot(im) / want.norm() - 1.0).abs() < 1e-3,
        "{} vs {}",
        re.hypot(im),
        want.norm()
    );
    assert!(
        (im.atan2(re) - want.arg()).abs() < 1e-2,
        "{} vs {}",
        im.atan2(re),
        want.arg()
    );
}

/// Issue 24: on a signal that never crosses the trigger level, AUTO waited forever and
/// the panel's screen stayed blank. AUTO free-runs after a sweep's length without a
/// trigger, as a real scope does, showing the flat signal where it is; REPEAT still waits
/// for its trigger, and AUTO on a triggering signal still sweeps from the trigger.
#[test]
fn auto_free_runs_without_a_trigger_and_repeat_waits() {
    let sweep = (10.0 * 0.002 * RATE) as usize;
    let flat = vec![0.1; 3 * sweep];
    let mut out = vec![0.0; flat.len()];
    let mut repeat = scope(Slope::Rising, SweepMode::Repeat);
    repeat.process(&flat, &mut out);
    assert!(repeat.trace().is_none(), "repeat swept without a trigger");
    let mut auto = scope(Slope::Rising, SweepMode::Auto);
    auto.process(&flat, &mut out);
    let trace = auto.trace().expect("auto shows the flat signal");
    assert_eq!(trace.len(), sweep);
    assert!(
        trace.iter().all(|&(_, div)| (div - 0.2).abs() < 1e-12),
        "0.1 V at 0.5 V/div"
    );
    let mut triggered = scope(Slope::Rising, SweepMode::Auto);
    let input = sine(100.0, 1.0, 20_000, 0);
    let mut through = vec![0.0; input.len()];
    triggered.process(&input, &mut through);
    let first = triggered.trace().expect("a sweep")[0].1;
    assert!(
        (first - 0.5).abs() < 0.02,
        "auto starts at the trigger level: {first}"
    );
}
