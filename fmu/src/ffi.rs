//! FMI 3.0's C functions for co-simulation, each translating to [`Instance`]: pointers
//! checked, every call inside `catch_unwind` (a panic is logged and returned as
//! `fmi3Error`, never crossing into the importer), every refusal logged through the
//! importer's callback with the function's name. The functions of capabilities not
//! offered are in `ffi_unoffered.rs`.

use std::ffi::{CStr, CString, c_char, c_int, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};

use rig::RigTopology;

use crate::error::FmuError;
use crate::instance::Instance;
use crate::model_description::{RIG_RESOURCE, instantiation_token};

/// fmi3Status.
pub type Status = c_int;
/// fmi3OK.
pub const OK: Status = 0;
/// fmi3Error.
pub const ERROR: Status = 3;

/// fmi3LogMessageCallback: environment, status, category, message.
pub type LogMessage =
    Option<unsafe extern "C" fn(*mut c_void, Status, *const c_char, *const c_char)>;

/// The importer's logger of one instance.
#[derive(Clone, Copy, Debug)]
pub struct Logger {
    environment: *mut c_void,
    callback: LogMessage,
    /// Whether the `logStep` category is on.
    steps: bool,
}

impl Logger {
    /// The importer's callback and environment, the `logStep` category off.
    pub fn new(environment: *mut c_void, callback: LogMessage) -> Self {
        Self {
            environment,
            callback,
            steps: false,
        }
    }

    /// Sends `message` in `category` with `status` (nothing without a callback).
    pub fn log(&self, status: Status, category: &str, message: &str) {
        let Some(callback) = self.callback else {
            return;
        };
        let category = CString::new(category).unwrap_or_default();
        let message = CString::new(message.replace('\0', " ")).unwrap_or_default();
        // SAFETY: the importer gave this callback and its environment for this instance.
        unsafe {
            callback(
                self.environment,
                status,
                category.as_ptr(),
                message.as_ptr(),
            )
        };
    }

    /// Logs a refusal or failure of `function` as `fmi3Error`.
    pub fn error(&self, function: &str, message: &str) {
        self.log(ERROR, "logStatusError", &format!("{function}: {message}"));
    }
}

/// What an fmi3Instance points to.
#[derive(Debug)]
pub struct Component {
    /// The instance.
    pub instance: Instance,
    /// Its logger.
    pub logger: Logger,
    name: String,
}

/// Runs `body` on the component behind `instance`, panics caught; a refusal is logged
/// under `function` and returned as `fmi3Error`.
///
/// # Safety
/// `instance` is null or a pointer `fmi3InstantiateCoSimulation` returned and not freed.
pub unsafe fn with_component(
    instance: *mut c_void,
    function: &str,
    body: impl FnOnce(&mut Component) -> Result<(), FmuError>,
) -> Status {
    if instance.is_null() {
        return ERROR;
    }
    // SAFETY: the caller's contract.
    let component = unsafe { &mut *instance.cast::<Component>() };
    match catch_unwind(AssertUnwindSafe(|| body(component))) {
        Ok(Ok(())) => OK,
        Ok(Err(e)) => {
            component.logger.error(function, &e.0);
            ERROR
        }
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            component.instance.fail();
            component.logger.error(
                function,
                &format!("internal fault ({what}); the instance must be reset or freed"),
            );
            ERROR
        }
    }
}

/// The `n` values at `ptr` (an empty slice for `n` = 0, whatever `ptr` is).
///
/// # Safety
/// For `n` > 0, `ptr` is null or points to `n` values.
pub unsafe fn slice<'a, T>(ptr: *const T, n: usize) -> Result<&'a [T], FmuError> {
    if n == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(FmuError(format!("a null array of {n} values")));
    }
    // SAFETY: the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(ptr, n) })
}

/// The `n` places at `ptr`, as [`slice()`] gives values: a mutable slice.
///
/// # Safety
/// For `n` > 0, `ptr` is null or points to `n` writable values.
pub unsafe fn slice_mut<'a, T>(ptr: *mut T, n: usize) -> Result<&'a mut [T], FmuError> {
    if n == 0 {
        return Ok(&mut []);
    }
    if ptr.is_null() {
        return Err(FmuError(format!("a null array of {n} values")));
    }
    // SAFETY: the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts_mut(ptr, n) })
}

/// A C string, or `None` for null or invalid UTF-8.
///
/// # Safety
/// `ptr` is null or a NUL-terminated string.
unsafe fn text(ptr: *const c_char) -> Option<String> {
    if ptr.is_null() {
        return None;
    }
    // SAFETY: the caller's contract.
    unsafe { CStr::from_ptr(ptr) }
        .to_str()
        .ok()
        .map(str::to_owned)
}

/// The FMI version the functions implement.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetVersion() -> *const c_char {
    c"3.0".as_ptr()
}

/// A co-simulation instance of the FMU's rig, read from `rig.json` in `resource_path`
/// and checked against `token`; null, with the reason logged, where that fails.
///
/// # Safety
/// Strings are null or NUL-terminated; `log_message` is null or a valid callback.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
    instance_name: *const c_char,
    token: *const c_char,
    resource_path: *const c_char,
    _visible: bool,
    logging_on: bool,
    _event_mode_used: bool,
    _early_return_allowed: bool,
    _required_intermediate: *const u32,
    _n_required_intermediate: usize,
    environment: *mut c_void,
    log_message: LogMessage,
    _intermediate_update: *const c_void,
) -> *mut c_void {
    let logger = Logger {
        steps: logging_on,
        ..Logger::new(environment, log_message)
    };
    let made = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: the caller's contract.
        let (name, token, path) =
            unsafe { (text(instance_name), text(token), text(resource_path)) };
        instantiate(name, token, path, logger)
    }));
    match made {
        Ok(Ok(component)) => Box::into_raw(Box::new(component)).cast(),
        Ok(Err(e)) => {
            logger.error("fmi3InstantiateCoSimulation", &e.0);
            std::ptr::null_mut()
        }
        Err(_) => {
            logger.error("fmi3InstantiateCoSimulation", "internal fault");
            std::ptr::null_mut()
        }
    }
}

fn instantiate(
    name: Option<String>,
    token: Option<String>,
    resource_path: Option<String>,
    logger: Logger,
) -> Result<Component, FmuError> {
    let name = name.ok_or_else(|| FmuError("no instance name".into()))?;
    let dir = resource_path.ok_or_else(|| {
        FmuError("no resource path: the FMU's rig is its resources/rig.json".into())
    })?;
    let path = std::path::Path::new(&dir).join(RIG_RESOURCE);
    let json = std::fs::read_to_string(&path)
        .map_err(|e| FmuError(format!("cannot read {}: {e}", path.display())))?;
    let expected = instantiation_token(&json);
    if token.as_deref() != Some(expected.as_str()) {
        return Err(FmuError(format!(
            "instantiation token {token:?} is not this FMU's {expected}: the model description and resources/rig.json differ"
        )));
    }
    let rig: RigTopology =
        serde_json::from_str(&json).map_err(|e| FmuError(format!("{}: {e}", path.display())))?;
    Ok(Component {
        instance: Instance::new(rig)?,
        logger,
        name,
    })
}

/// Frees an instance.
///
/// # Safety
/// `instance` is null or an instance not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeInstance(instance: *mut c_void) {
    if !instance.is_null() {
        // SAFETY: made by Box::into_raw in fmi3InstantiateCoSimulation.
        let _ = catch_unwind(|| drop(unsafe { Box::from_raw(instance.cast::<Component>()) }));
    }
}

/// Turns the `logStep` category on or off (errors are always logged).
///
/// # Safety
/// As [`with_component`]; `categories` holds `n_categories` strings.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetDebugLogging(
    instance: *mut c_void,
    logging_on: bool,
    n_categories: usize,
    categories: *const *const c_char,
) -> Status {
    let f = "fmi3SetDebugLogging";
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, f, |c| {
            for &category in slice(categories, n_categories)? {
                match text(category).as_deref() {
                    Some("logStep") => c.logger.steps = logging_on,
                    Some("logStatusError") => {}
                    other => {
                        return Err(FmuError(format!(
                            "unknown log category {other:?} (logStatusError, logStep)"
                        )));
                    }
                }
            }
            if n_categories == 0 {
                c.logger.steps = logging_on;
            }
            Ok(())
        })
    }
}

/// Enters initialization mode at `start_time`.
///
/// # Safety
/// As [`with_component`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3EnterInitializationMode(
    instance: *mut c_void,
    _tolerance_defined: bool,
    _tolerance: f64,
    start_time: f64,
    _stop_time_defined: bool,
    _stop_time: f64,
) -> Status {
    let f = "fmi3EnterInitializationMode";
    // SAFETY: the caller's contract.
    unsafe { with_component(instance, f, |c| c.instance.enter_initialization(start_time)) }
}

/// Leaves initialization mode: the plant is built at rest.
///
/// # Safety
/// As [`with_component`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3ExitInitializationMode(instance: *mut c_void) -> Status {
    let f = "fmi3ExitInitializationMode";
    // SAFETY: the caller's contract.
    unsafe { with_component(instance, f, |c| c.instance.exit_initialization()) }
}

/// Terminates the simulation (values stay readable).
///
/// # Safety
/// As [`with_component`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3Terminate(instance: *mut c_void) -> Status {
    // SAFETY: the caller's contract.
    unsafe { with_component(instance, "fmi3Terminate", |c| c.instance.terminate()) }
}

/// Back to the state after instantiation.
///
/// # Safety
/// As [`with_component`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3Reset(instance: *mut c_void) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, "fmi3Reset", |c| {
            c.instance.reset();
            Ok(())
        })
    }
}

/// Advances the plant exactly over one communication step, the inputs held.
///
/// # Safety
/// As [`with_component`]; the out-pointers are null or writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn fmi3DoStep(
    instance: *mut c_void,
    current_communication_point: f64,
    communication_step_size: f64,
    _no_set_fmu_state_prior: bool,
    event_handling_needed: *mut bool,
    terminate_simulation: *mut bool,
    early_return: *mut bool,
    last_successful_time: *mut f64,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, "fmi3DoStep", |c| {
            let before = c.instance.impact_total();
            let result = c
                .instance
                .do_step(current_communication_point, communication_step_size);
            for (ptr, value) in [
                (event_handling_needed, false),
                (terminate_simulation, false),
                (early_return, false),
            ] {
                if !ptr.is_null() {
                    *ptr = value;
                }
            }
            if !last_successful_time.is_null() {
                *last_successful_time = c.instance.time_s();
            }
            if result.is_ok() && c.logger.steps {
                let message = format!(
                    "{}: step to {} s, {} impacts",
                    c.name,
                    c.instance.time_s(),
                    c.instance.impact_total() - before
                );
                c.logger.log(OK, "logStep", &message);
            }
            result
        })
    }
}
