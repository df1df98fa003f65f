//! The fused multiply-add path chosen at run time. The plant's inner loops use
//! `f64::mul_add` (one rounding, the same bytes on every CPU). Where the CPU has FMA and
//! AVX2 (x86-64-v3: every x86 server since about 2015), those loops run in functions
//! compiled for them (`#[target_feature]`), called after [`available`] says yes; elsewhere
//! the same loops run compiled for baseline x86-64, where each `mul_add` is a (correct,
//! slower) library call. Both paths give the same bytes.

/// Whether this CPU has FMA and AVX2 (the answer is cached by the standard library).
#[inline]
pub(crate) fn available() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("fma") && std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}
