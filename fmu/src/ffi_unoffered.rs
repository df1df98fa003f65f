//! The rest of FMI 3.0's C interface, exported so that every importer finds every symbol:
//! getters and setters of types the FMU has no variable of (nothing to do for no value
//! references, else `fmi3Error`), and the functions of capabilities not offered (model
//! exchange, scheduled execution, event mode, clocks, configuration mode, derivatives,
//! dependencies, serialized states), each logging why and returning `fmi3Error`.

use std::ffi::{c_char, c_int, c_void};

use crate::error::FmuError;
use crate::ffi::{ERROR, LogMessage, Status, with_component};

/// Why a function is not offered.
const WHY: &str = "not offered: this FMU offers co-simulation without event mode, clocks, structural parameters, derivatives, dependency information or serialized states (docs/fmu.md)";

/// A getter or setter of a type no variable has.
macro_rules! absent_type {
    ($name:ident, $what:literal, $values:ty) => {
        /// No variable has this type: nothing to do for no value references, else an error.
        ///
        /// # Safety
        /// As `fmi3GetFloat64`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            instance: *mut c_void,
            vrs: *const u32,
            n_vrs: usize,
            _values: $values,
            _n_values: usize,
        ) -> Status {
            // SAFETY: the caller's contract.
            unsafe { absent(instance, stringify!($name), $what, vrs, n_vrs) }
        }
    };
}

/// Refuses value references of a type the FMU has no variable of.
///
/// # Safety
/// As `fmi3GetFloat64`.
unsafe fn absent(
    instance: *mut c_void,
    function: &str,
    what: &str,
    vrs: *const u32,
    n_vrs: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, function, |_| match n_vrs {
            0 => Ok(()),
            _ => Err(FmuError(format!(
                "this FMU {what} (value reference {})",
                if vrs.is_null() { 0 } else { *vrs }
            ))),
        })
    }
}

absent_type!(fmi3GetFloat32, "has no Float32 variables", *mut f32);
absent_type!(fmi3GetInt8, "has no Int8 variables", *mut i8);
absent_type!(fmi3GetUInt8, "has no UInt8 variables", *mut u8);
absent_type!(fmi3GetInt16, "has no Int16 variables", *mut i16);
absent_type!(fmi3GetUInt16, "has no UInt16 variables", *mut u16);
absent_type!(fmi3GetUInt32, "has no UInt32 variables", *mut u32);
absent_type!(fmi3GetUInt64, "has no UInt64 variables", *mut u64);
absent_type!(fmi3GetBoolean, "has no Boolean variables", *mut bool);
absent_type!(fmi3GetString, "has no String variables", *mut *const c_char);
absent_type!(fmi3SetFloat32, "has no Float32 variables", *const f32);
absent_type!(fmi3SetInt8, "has no Int8 variables", *const i8);
absent_type!(fmi3SetUInt8, "has no UInt8 variables", *const u8);
absent_type!(fmi3SetInt16, "has no Int16 variables", *const i16);
absent_type!(fmi3SetUInt16, "has no UInt16 variables", *const u16);
absent_type!(
    fmi3SetInt32,
    "has Int32 variables only as outputs, which cannot be set",
    *const i32
);
absent_type!(fmi3SetUInt32, "has no UInt32 variables", *const u32);
absent_type!(
    fmi3SetInt64,
    "has Int64 variables only as outputs, which cannot be set",
    *const i64
);
absent_type!(fmi3SetUInt64, "has no UInt64 variables", *const u64);
absent_type!(fmi3SetBoolean, "has no Boolean variables", *const bool);
absent_type!(
    fmi3SetString,
    "has no String variables",
    *const *const c_char
);

/// No Binary variables.
///
/// # Safety
/// As `fmi3GetFloat64`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetBinary(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    _sizes: *mut usize,
    _values: *mut *const u8,
    _n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        absent(
            instance,
            "fmi3GetBinary",
            "has no Binary variables",
            vrs,
            n_vrs,
        )
    }
}

/// No Binary variables.
///
/// # Safety
/// As `fmi3GetFloat64`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetBinary(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    _sizes: *const usize,
    _values: *const *const u8,
    _n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        absent(
            instance,
            "fmi3SetBinary",
            "has no Binary variables",
            vrs,
            n_vrs,
        )
    }
}

/// No clocks.
///
/// # Safety
/// As `fmi3GetFloat64`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetClock(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    _values: *mut bool,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { absent(instance, "fmi3GetClock", "has no clocks", vrs, n_vrs) }
}

/// No clocks.
///
/// # Safety
/// As `fmi3GetFloat64`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetClock(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    _values: *const bool,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { absent(instance, "fmi3SetClock", "has no clocks", vrs, n_vrs) }
}

/// A function of a capability not offered: logs why, returns `fmi3Error`.
macro_rules! unoffered {
    ($name:ident ( $($arg:ident : $ty:ty),* )) => {
        /// Not offered (see the module's header): logs why and returns `fmi3Error`.
        ///
        /// # Safety
        /// `instance` is null or an instance of this FMU.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(instance: *mut c_void, $($arg: $ty),*) -> Status {
            // SAFETY: the caller's contract.
            unsafe { with_component(instance, stringify!($name), |_| Err(FmuError(WHY.into()))) }
        }
    };
}

unoffered!(fmi3EnterEventMode());
unoffered!(fmi3EnterStepMode());
unoffered!(fmi3EnterConfigurationMode());
unoffered!(fmi3ExitConfigurationMode());
unoffered!(fmi3EvaluateDiscreteStates());
unoffered!(fmi3EnterContinuousTimeMode());
unoffered!(fmi3GetNumberOfVariableDependencies(_vr: u32, _n: *mut usize));
unoffered!(fmi3GetVariableDependencies(
    _dependent: u32,
    _element_of_dependent: *mut usize,
    _independents: *mut u32,
    _element_of_independents: *mut usize,
    _kinds: *mut c_int,
    _n: usize
));
unoffered!(fmi3SerializedFMUStateSize(_state: *mut c_void, _size: *mut usize));
unoffered!(fmi3SerializeFMUState(_state: *mut c_void, _bytes: *mut u8, _size: usize));
unoffered!(fmi3DeserializeFMUState(_bytes: *const u8, _size: usize, _state: *mut *mut c_void));
unoffered!(fmi3GetDirectionalDerivative(
    _unknowns: *const u32,
    _n_unknowns: usize,
    _knowns: *const u32,
    _n_knowns: usize,
    _seed: *const f64,
    _n_seed: usize,
    _sensitivity: *mut f64,
    _n_sensitivity: usize
));
unoffered!(fmi3GetAdjointDerivative(
    _unknowns: *const u32,
    _n_unknowns: usize,
    _knowns: *const u32,
    _n_knowns: usize,
    _seed: *const f64,
    _n_seed: usize,
    _sensitivity: *mut f64,
    _n_sensitivity: usize
));
unoffered!(fmi3GetIntervalDecimal(_vrs: *const u32, _n: usize, _intervals: *mut f64, _qualifiers: *mut c_int));
unoffered!(fmi3GetIntervalFraction(
    _vrs: *const u32,
    _n: usize,
    _counters: *mut u64,
    _resolutions: *mut u64,
    _qualifiers: *mut c_int
));
unoffered!(fmi3GetShiftDecimal(_vrs: *const u32, _n: usize, _shifts: *mut f64));
unoffered!(fmi3GetShiftFraction(_vrs: *const u32, _n: usize, _counters: *mut u64, _resolutions: *mut u64));
unoffered!(fmi3SetIntervalDecimal(_vrs: *const u32, _n: usize, _intervals: *const f64));
unoffered!(fmi3SetIntervalFraction(_vrs: *const u32, _n: usize, _counters: *const u64, _resolutions: *const u64));
unoffered!(fmi3SetShiftDecimal(_vrs: *const u32, _n: usize, _shifts: *const f64));
unoffered!(fmi3SetShiftFraction(_vrs: *const u32, _n: usize, _counters: *const u64, _resolutions: *const u64));
unoffered!(fmi3UpdateDiscreteStates(
    _discrete_states_need_update: *mut bool,
    _terminate: *mut bool,
    _nominals_changed: *mut bool,
    _values_changed: *mut bool,
    _next_event_time_defined: *mut bool,
    _next_event_time: *mut f64
));
unoffered!(fmi3CompletedIntegratorStep(_no_set_prior: bool, _enter_event_mode: *mut bool, _terminate: *mut bool));
unoffered!(fmi3SetTime(_time: f64));
unoffered!(fmi3SetContinuousStates(_states: *const f64, _n: usize));
unoffered!(fmi3GetContinuousStateDerivatives(_derivatives: *mut f64, _n: usize));
unoffered!(fmi3GetEventIndicators(_indicators: *mut f64, _n: usize));
unoffered!(fmi3GetContinuousStates(_states: *mut f64, _n: usize));
unoffered!(fmi3GetNominalsOfContinuousStates(_nominals: *mut f64, _n: usize));
unoffered!(fmi3GetNumberOfEventIndicators(_n: *mut usize));
unoffered!(fmi3GetNumberOfContinuousStates(_n: *mut usize));
unoffered!(fmi3GetOutputDerivatives(
    _vrs: *const u32,
    _n_vrs: usize,
    _orders: *const i32,
    _values: *mut f64,
    _n_values: usize
));
unoffered!(fmi3ActivateModelPartition(_clock: u32, _activation_time: f64));

/// Model exchange is not offered: logs why and returns null.
///
/// # Safety
/// `log_message` is null or a valid callback.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3InstantiateModelExchange(
    _instance_name: *const c_char,
    _token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    environment: *mut c_void,
    log_message: LogMessage,
) -> *mut c_void {
    refuse_interface(environment, log_message, "model exchange")
}

/// Scheduled execution is not offered: logs why and returns null.
///
/// # Safety
/// `log_message` is null or a valid callback.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
    _instance_name: *const c_char,
    _token: *const c_char,
    _resource_path: *const c_char,
    _visible: bool,
    _logging_on: bool,
    environment: *mut c_void,
    log_message: LogMessage,
    _clock_update: *const c_void,
    _lock_preemption: *const c_void,
    _unlock_preemption: *const c_void,
) -> *mut c_void {
    refuse_interface(environment, log_message, "scheduled execution")
}

fn refuse_interface(environment: *mut c_void, log_message: LogMessage, what: &str) -> *mut c_void {
    let logger = crate::ffi::Logger::new(environment, log_message);
    logger.log(
        ERROR,
        "logStatusError",
        &format!("{what} is not offered: this FMU is for co-simulation only"),
    );
    std::ptr::null_mut()
}
