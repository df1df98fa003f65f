//! Where a rig check's fault lies in the rig file: the field as the file writes it
//! (`shaft `input`.stiffness_nm_per_rad`), the name of the item it lies in, and its span
//! (line and column) in the text, for the reader's errors.

use std::ops::Range;

use rig::{RigTopology, TopologyPlace};
use toml::Spanned;

use super::read_rig_planetary::FRAME;
use super::rig_file_toml::{PlanetaryToml, RigFileToml};

/// The field a check's fault names, as the file writes it (`shaft `input`.stiffness…`).
pub(super) fn field_name(rig: &RigTopology, place: &TopologyPlace) -> String {
    // A shaft to the frame is a `[[shaft]]` in the file.
    let table = match place.table {
        "frame_shaft" => "shaft",
        table => table,
    };
    match place_item(rig, place) {
        Some(name) => format!("{table} `{name}`.{}", place.field),
        None => format!("{table}.{}", place.field),
    }
}

/// Where in a `[[planetary]]` table a check's fault on `field` lies.
fn planetary_span(p: &PlanetaryToml, field: &str) -> Range<usize> {
    let given = |v: &Option<Spanned<f64>>| v.as_ref().map(Spanned::span);
    match field {
        "sun" => Some(p.sun.span()),
        "ring" => Some(p.ring.span()),
        "carrier" => Some(p.carrier.span()),
        "planets" => Some(p.planets.span()),
        "planet_angles_deg" => p
            .planet_angles_deg
            .as_ref()
            .map_or(Some(p.planets.span()), |a| Some(a.span())),
        "planet_inertia_kgm2" => Some(p.planet_inertia_kgm2.span()),
        "planet_pin_errors_um" => p.planet_pin_errors_um.as_ref().map(Spanned::span),
        "planet_mass_kg" => given(&p.planet_mass_kg),
        "planet_bearing_stiffness_n_per_m" => given(&p.planet_bearing_stiffness_n_per_m),
        "planet_bearing_damping_ns_per_m" => given(&p.planet_bearing_damping_ns_per_m),
        "teeth" => Some(p.teeth.span()),
        "module_m" => Some(p.module_m.span()),
        "pressure_angle_deg" => given(&p.pressure_angle_deg),
        "base_diameter_m" => p.base_diameter_m.as_ref().map(Spanned::span),
        "carrier_radius_m" => given(&p.carrier_radius_m),
        "sun_planet" => Some(p.sun_planet.span()),
        "ring_planet" => Some(p.ring_planet.span()),
        "fault" => p.fault.first().map(|f| f.gear.span()),
        "ring_sensor" => p.ring_sensor.as_ref().map(Spanned::span),
        _ => None,
    }
    .unwrap_or(p.name.span())
}

/// The name of the body, shaft or mesh a check's fault lies in, if it lies in one.
pub(super) fn place_item<'a>(rig: &'a RigTopology, place: &TopologyPlace) -> Option<&'a str> {
    match place.table {
        "body" => rig.bodies.get(place.index).map(|b| b.name.as_str()),
        "shaft" => rig.shafts.get(place.index).map(|s| s.name.as_str()),
        "mesh" => rig.meshes.get(place.index).map(|m| m.name.as_str()),
        "frame_shaft" => rig.frame_shafts.get(place.index).map(|s| s.name.as_str()),
        "planetary" => rig.planetary.get(place.index).map(|s| s.name.as_str()),
        _ => None,
    }
}

/// Where in the file a check's fault lies (0..0, no line, where the file has no such value).
pub(super) fn span_of(file: &RigFileToml, place: &TopologyPlace) -> Range<usize> {
    let i = place.index;
    let span = match (place.table, place.field) {
        ("body", "inertia_kgm2") => file.bodies.get(i).map(|b| b.inertia_kgm2.span()),
        ("body", "mass_kg") => file
            .bodies
            .get(i)
            .and_then(|b| b.mass_kg.as_ref().map(Spanned::span)),
        ("body", "bearing_stiffness_n_per_m") => file
            .bodies
            .get(i)
            .and_then(|b| b.bearing_stiffness_n_per_m.as_ref().map(Spanned::span)),
        ("body", "bearing_damping_ns_per_m") => file
            .bodies
            .get(i)
            .and_then(|b| b.bearing_damping_ns_per_m.as_ref().map(Spanned::span)),
        ("body", "drag_nms_per_rad") => file
            .bodies
            .get(i)
            .and_then(|b| b.drag_nms_per_rad.as_ref().map(Spanned::span)),
        ("body", _) => file.bodies.get(i).map(|b| b.name.span()),
        ("shaft", "stiffness_nm_per_rad") => {
            file.shafts.get(i).map(|s| s.stiffness_nm_per_rad.span())
        }
        ("shaft", "damping_nms_per_rad") => file
            .shafts
            .get(i)
            .and_then(|s| s.damping_nms_per_rad.as_ref().map(Spanned::span)),
        ("shaft", _) => file.shafts.get(i).map(|s| s.between.span()),
        ("mesh", field) => file.meshes.get(i).and_then(|m| match field {
            "teeth" => Some(m.teeth.span()),
            "module_m" => Some(m.module_m.span()),
            "backlash_mm" => Some(m.backlash_mm.span()),
            "centre_distance_shift_mm" => m.centre_distance_shift_mm.as_ref().map(Spanned::span),
            "stiffness_n_per_m" => m.stiffness_n_per_m.as_ref().map(Spanned::span),
            "damping_ns_per_m" => m.damping_ns_per_m.as_ref().map(Spanned::span),
            "pressure_angle_deg" => m.pressure_angle_deg.as_ref().map(Spanned::span),
            "driven" => Some(m.driven.span()),
            "pairs" => m.pairs.as_ref().map(Spanned::span),
            "double_pair_ratio" => m.double_pair_ratio.as_ref().map(Spanned::span),
            "addendum_coefficient" => m.addendum_coefficient.as_ref().map(Spanned::span),
            "stiffness_smoothing" => m.stiffness_smoothing.as_ref().map(Spanned::span),
            "backlash_variation" => m.backlash_variation.as_ref().map(Spanned::span),
            "te_once_per_rev_um" => m.te_once_per_rev_um.as_ref().map(Spanned::span),
            "te_mesh_frequency_um" => m.te_mesh_frequency_um.as_ref().map(Spanned::span),
            "fault" => m.fault.first().map(|f| f.tooth.span()),
            "run_out_driver_um" => m.run_out_driver_um.as_ref().map(Spanned::span),
            "run_out_driven_um" => m.run_out_driven_um.as_ref().map(Spanned::span),
            "tooth_spacing_error_um" => m.tooth_spacing_error_um.as_ref().map(Spanned::span),
            "gear_error_c2_nm" => m.gear_error_c2_nm.as_ref().map(Spanned::span),
            "gear_error_c3_nm" => m.gear_error_c3_nm.as_ref().map(Spanned::span),
            _ => Some(m.name.span()),
        }),
        ("frame_shaft", field) => file
            .shafts
            .iter()
            .filter(|s| s.between.get_ref().iter().any(|b| b.get_ref() == FRAME))
            .nth(i)
            .map(|s| match field {
                "stiffness_nm_per_rad" => s.stiffness_nm_per_rad.span(),
                "damping_nms_per_rad" => s
                    .damping_nms_per_rad
                    .as_ref()
                    .map_or(s.between.span(), Spanned::span),
                _ => s.between.span(),
            }),
        ("planetary", field) => file.planetary.get(i).map(|p| planetary_span(p, field)),
        ("locked_torque", _) => file.locked_torque.as_ref().map(|l| l.torque_nm.span()),
        ("motor", field) => file.motor.as_ref().and_then(|m| match field {
            "torque_limit_nm" => m.torque_limit_nm.as_ref().map(Spanned::span),
            "speed_loop_hz" => m.speed_loop_hz.as_ref().map(Spanned::span),
            "speed_loop_damping_ratio" => m.speed_loop_damping_ratio.as_ref().map(Spanned::span),
            "feedback_filter_hz" => m.feedback_filter_hz.as_ref().map(Spanned::span),
            "rated_power_w" => m.rated_power_w.as_ref().map(Spanned::span),
            "rated_speed_rpm" => m.rated_speed_rpm.as_ref().map(Spanned::span),
            "full_load_current_a" => m.full_load_current_a.as_ref().map(Spanned::span),
            "current_limit_pct" => m.current_limit_pct.as_ref().map(Spanned::span),
            _ => Some(m.body.span()),
        }),
        ("gauge", field) => file.gauge.as_ref().map(|g| match field {
            "shear_modulus_pa" => g
                .shear_modulus_pa
                .as_ref()
                .map_or(g.shaft.span(), Spanned::span),
            _ => g.diameter_m.span(),
        }),
        ("brake", field) => file.brake.as_ref().map(|b| {
            let value = match field {
                "drag_nm" => &b.drag_nm,
                "critical_speed_rpm" => &b.critical_speed_rpm,
                _ => &b.slope_nms_per_rad,
            };
            value.as_ref().map_or(b.body.span(), Spanned::span)
        }),
        _ => None,
    };
    span.unwrap_or(0..0)
}
