//! Drives the FMU's C functions (`testrig_fmu::ffi`, the ones the shared library exports)
//! as an importer does: instantiation from a resources folder, a logger collecting every
//! message, typed gets and sets by variable name, steps.

use std::ffi::{CStr, CString, c_char, c_int, c_void};
use std::path::Path;
use std::sync::Mutex;

use rig::RigTopology;
use testrig_fmu::ffi::{self, ERROR, OK};
use testrig_fmu::ffi_values;
use testrig_fmu::{Kind, Variable, instantiation_token, variables};

/// The messages an instance logged.
pub type Log = Mutex<Vec<String>>;

/// The importer's logger: appends "status category: message" to the `Log` behind `env`.
pub unsafe extern "C" fn collect(
    env: *mut c_void,
    status: c_int,
    category: *const c_char,
    message: *const c_char,
) {
    // SAFETY: env is the Box<Log> an Fmu holds; the strings are the FMU's.
    let (log, category, message) = unsafe {
        (
            &*env.cast::<Log>(),
            CStr::from_ptr(category).to_string_lossy(),
            CStr::from_ptr(message).to_string_lossy(),
        )
    };
    log.lock()
        .expect("log")
        .push(format!("{status} {category}: {message}"));
}

/// One instance of a rig's FMU.
pub struct Fmu {
    pub instance: *mut c_void,
    pub log: Box<Log>,
    vars: Vec<Variable>,
}

impl Fmu {
    /// Instantiates `rig` with its resources in `dir`; `token` `None` gives the right one.
    pub fn new(rig: &RigTopology, dir: &Path, token: Option<&str>) -> Self {
        let json = serde_json::to_string_pretty(rig).expect("json");
        std::fs::write(dir.join("rig.json"), &json).expect("resource");
        let token = CString::new(token.map_or_else(|| instantiation_token(&json), str::to_owned))
            .expect("token");
        let name = CString::new("rig").expect("name");
        let path = CString::new(format!("{}/", dir.display())).expect("path");
        let log: Box<Log> = Box::new(Mutex::new(Vec::new()));
        let env = (&*log as *const Log).cast_mut().cast::<c_void>();
        // SAFETY: valid strings and callback; the log outlives the instance.
        let instance = unsafe {
            ffi::fmi3InstantiateCoSimulation(
                name.as_ptr(),
                token.as_ptr(),
                path.as_ptr(),
                false,
                false,
                false,
                false,
                std::ptr::null(),
                0,
                env,
                Some(collect),
                std::ptr::null(),
            )
        };
        Self {
            instance,
            log,
            vars: variables(rig),
        }
    }

    /// The value reference of `name`.
    pub fn vr(&self, name: &str) -> u32 {
        self.vars
            .iter()
            .find(|v| v.name == name)
            .unwrap_or_else(|| panic!("no variable {name}"))
            .value_reference
    }

    /// The messages logged so far.
    pub fn messages(&self) -> Vec<String> {
        self.log.lock().expect("log").clone()
    }

    /// Sets a Float64 by name; the status.
    pub fn set(&mut self, name: &str, value: f64) -> c_int {
        let vr = self.vr(name);
        // SAFETY: one value reference, one value.
        unsafe { ffi_values::fmi3SetFloat64(self.instance, &vr, 1, &value, 1) }
    }

    /// Enters and leaves initialization at t = 0.
    pub fn initialize(&mut self) {
        // SAFETY: a live instance.
        unsafe {
            assert_eq!(
                ffi::fmi3EnterInitializationMode(self.instance, false, 0.0, 0.0, false, 0.0),
                OK
            );
            assert_eq!(ffi::fmi3ExitInitializationMode(self.instance), OK);
        }
    }

    /// One communication step; the status.
    pub fn step(&mut self, t_s: f64, h_s: f64) -> c_int {
        let mut flags = [false; 3];
        let mut last = 0.0;
        // SAFETY: writable out-places.
        unsafe {
            ffi::fmi3DoStep(
                self.instance,
                t_s,
                h_s,
                true,
                &mut flags[0],
                &mut flags[1],
                &mut flags[2],
                &mut last,
            )
        }
    }

    /// Every output, as f64, in value-reference order.
    pub fn outputs(&mut self) -> Vec<f64> {
        let outputs: Vec<(u32, Kind)> = self
            .vars
            .iter()
            .filter(|v| v.causality == testrig_fmu::Causality::Output)
            .map(|v| (v.value_reference, v.kind))
            .collect();
        outputs
            .into_iter()
            .map(|(vr, kind)| self.get(vr, kind).expect("output"))
            .collect()
    }

    /// One variable's value as f64, or the status where refused.
    pub fn get(&mut self, vr: u32, kind: Kind) -> Result<f64, c_int> {
        // SAFETY: one value reference, one place.
        let (status, value) = unsafe {
            match kind {
                Kind::Float64 => {
                    let mut x = 0.0;
                    (
                        ffi_values::fmi3GetFloat64(self.instance, &vr, 1, &mut x, 1),
                        x,
                    )
                }
                Kind::Int32 => {
                    let mut x = 0;
                    let s = ffi_values::fmi3GetInt32(self.instance, &vr, 1, &mut x, 1);
                    (s, f64::from(x))
                }
                Kind::Int64 => {
                    let mut x = 0;
                    let s = ffi_values::fmi3GetInt64(self.instance, &vr, 1, &mut x, 1);
                    (s, x as f64)
                }
            }
        };
        if status == OK { Ok(value) } else { Err(status) }
    }

    /// A Float64 by name.
    pub fn float(&mut self, name: &str) -> f64 {
        let vr = self.vr(name);
        self.get(vr, Kind::Float64).expect("float")
    }

    /// Whether a call returned fmi3Error and logged a message containing `text`.
    pub fn refused(&self, status: c_int, text: &str) -> bool {
        status == ERROR && self.messages().iter().any(|m| m.contains(text))
    }
}

impl Drop for Fmu {
    fn drop(&mut self) {
        // SAFETY: the instance (or null) this Fmu made.
        unsafe { ffi::fmi3FreeInstance(self.instance) };
    }
}
