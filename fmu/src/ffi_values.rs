//! FMI 3.0's typed getters and setters the FMU has variables for (Float64, Int32 contact
//! states, Int64 impact counts): every variable a scalar, each value reference checked by
//! [`Instance`], a refused value leaving the variable as it was.

use std::ffi::c_void;

use crate::error::FmuError;
use crate::ffi::{Status, slice, slice_mut, with_component};
use crate::instance::Instance;

/// Reads Float64 variables.
///
/// # Safety
/// As [`with_component`]; the arrays hold the counts given.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFloat64(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *mut f64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        get_values(
            instance,
            "fmi3GetFloat64",
            (vrs, n_vrs),
            (values, n_values),
            |i, vr| i.get_float64(vr),
        )
    }
}

/// Reads Int32 variables (contact states).
///
/// # Safety
/// As [`fmi3GetFloat64`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetInt32(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *mut i32,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        get_values(
            instance,
            "fmi3GetInt32",
            (vrs, n_vrs),
            (values, n_values),
            |i, vr| i.get_int32(vr),
        )
    }
}

/// Reads Int64 variables (impact counts).
///
/// # Safety
/// As [`fmi3GetFloat64`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetInt64(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *mut i64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        get_values(
            instance,
            "fmi3GetInt64",
            (vrs, n_vrs),
            (values, n_values),
            |i, vr| i.get_int64(vr),
        )
    }
}

/// Sets Float64 parameters and inputs; a refused value leaves the variable as it was.
///
/// # Safety
/// As [`fmi3GetFloat64`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFloat64(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *const f64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, "fmi3SetFloat64", |c| {
            let vrs = slice(vrs, n_vrs)?;
            let values = slice(values, n_values)?;
            check_counts(vrs.len(), values.len())?;
            vrs.iter()
                .zip(values)
                .try_for_each(|(&vr, &v)| c.instance.set_float64(vr, v))
        })
    }
}

/// Reads each of `vrs` with `get` into `values`.
///
/// # Safety
/// As [`fmi3GetFloat64`].
unsafe fn get_values<T>(
    instance: *mut c_void,
    function: &str,
    (vrs, n_vrs): (*const u32, usize),
    (values, n_values): (*mut T, usize),
    get: impl Fn(&mut Instance, u32) -> Result<T, FmuError>,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_component(instance, function, |c| {
            let vrs = slice(vrs, n_vrs)?;
            let out = slice_mut(values, n_values)?;
            check_counts(vrs.len(), out.len())?;
            for (place, &vr) in out.iter_mut().zip(vrs) {
                *place = get(&mut c.instance, vr)?;
            }
            Ok(())
        })
    }
}

/// Every variable is a scalar: as many values as value references.
pub fn check_counts(vrs: usize, values: usize) -> Result<(), FmuError> {
    if vrs != values {
        return Err(FmuError(format!(
            "{vrs} value references but {values} values (every variable is a scalar)"
        )));
    }
    Ok(())
}
