//! FMI 3.0's FMU state: the whole instance saved, restored and freed (serialization is
//! not offered, `ffi_unoffered.rs`).

use std::ffi::c_void;

use crate::error::FmuError;
use crate::ffi::{Status, with_component};
use crate::instance::Instance;

/// Saves the instance's whole state (a new one, or into `*state` if it holds one).
///
/// # Safety
/// As [`with_component`]; `state` is writable and holds null or a state of this FMU.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFMUState(instance: *mut c_void, state: *mut *mut c_void) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, "fmi3GetFMUState", |c| {
            if state.is_null() {
                return Err(FmuError("a null place for the state".into()));
            }
            let saved = c.instance.clone();
            if (*state).is_null() {
                *state = Box::into_raw(Box::new(saved)).cast();
            } else {
                *(*state).cast::<Instance>() = saved;
            }
            Ok(())
        })
    }
}

/// Restores a state saved by [`fmi3GetFMUState`].
///
/// # Safety
/// As [`with_component`]; `state` is a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFMUState(instance: *mut c_void, state: *mut c_void) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, "fmi3SetFMUState", |c| {
            if state.is_null() {
                return Err(FmuError("a null state".into()));
            }
            c.instance = (*state.cast::<Instance>()).clone();
            Ok(())
        })
    }
}

/// Frees a saved state and sets `*state` to null.
///
/// # Safety
/// As [`with_component`]; `state` is null or holds null or a state not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeFMUState(
    instance: *mut c_void,
    state: *mut *mut c_void,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, "fmi3FreeFMUState", |_| {
            if !state.is_null() && !(*state).is_null() {
                drop(Box::from_raw((*state).cast::<Instance>()));
                *state = std::ptr::null_mut();
            }
            Ok(())
        })
    }
}
