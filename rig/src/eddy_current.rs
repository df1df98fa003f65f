//! The eddy-current brake's characteristic: at a fixed excitation its torque follows
//! T ∝ g(ω) = 2x/(1 + x²), x = ω/ω_c (Wouterse 1991), peaking at the critical speed ω_c.
//! The plant linearises it about the set point where it brakes with the set torque.

/// Slope (N m s/rad) of the brake's torque with its speed at its set speed `speed_rad_s`,
/// braking `torque_nm` there, critical speed `critical_rad_s`: T(ω) = T_set g(ω)/g(Ω),
/// dT/dω = T_set (1 − x²)/((1 + x²) Ω). Positive below the critical speed (the brake
/// damps), negative above it; 0 when the characteristic is off (ω_c ≤ 0) or the brake
/// stands.
pub fn characteristic_slope_nms_per_rad(
    torque_nm: f64,
    speed_rad_s: f64,
    critical_rad_s: f64,
) -> f64 {
    if critical_rad_s <= 0.0 || speed_rad_s <= 0.0 {
        return 0.0;
    }
    let x2 = (speed_rad_s / critical_rad_s).powi(2);
    torque_nm * (1.0 - x2) / ((1.0 + x2) * speed_rad_s)
}
