//! A fault on one tooth of a mesh: a root crack, a pit or a broken tooth, seeded on the
//! driving or the driven gear. While the faulted tooth's pair is in mesh its stiffness
//! (and damping) scale by what is left of it: a crack lowers the pair's stiffness as the
//! potential-energy method gives (`mesh_stiffness.rs`), a pitted share of the contact
//! width carries no load (the pair's stiffness is proportional to its contact width), a
//! broken share of the face carries nothing. A tooth broken across its whole face leaves the pair as free
//! play: where it alone would carry the load the gears part, and the next pair strikes.

use serde::{Deserialize, Serialize};

/// Which gear of a mesh carries the fault.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FaultedGear {
    /// The mesh's driving gear.
    Driver,
    /// The mesh's driven gear.
    Driven,
}

impl FaultedGear {
    /// Its name as rig files write it: `driver` or `driven`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Driver => "driver",
            Self::Driven => "driven",
        }
    }
}

/// The kind of a tooth fault.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FaultKind {
    /// A root crack: `severity` is its depth over the tooth's thickness at the root.
    Crack,
    /// Pitting: `severity` is the pitted share of the contact width.
    Pit,
    /// A broken tooth: `severity` is the broken-off share of the face.
    Broken,
}

impl FaultKind {
    /// The kinds by name, as rig files write them.
    pub const NAMES: [&'static str; 3] = ["crack", "pit", "broken"];

    /// Its name as rig files write it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Crack => "crack",
            Self::Pit => "pit",
            Self::Broken => "broken",
        }
    }

    /// The kind named `name`.
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "crack" => Some(Self::Crack),
            "pit" => Some(Self::Pit),
            "broken" => Some(Self::Broken),
            _ => None,
        }
    }
}

/// A fault on one tooth.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ToothFault {
    /// The gear whose tooth it is.
    pub gear: FaultedGear,
    /// The tooth, 1..=z of that gear: tooth 1 of each gear is the pair in mesh with the
    /// driver at angle 0, the others numbered in the order they come into mesh.
    pub tooth: u32,
    /// What it is.
    pub kind: FaultKind,
    /// How bad, 0..=1 (the share the kind names).
    pub severity: f64,
}

impl ToothFault {
    /// Whether the fault acts only while its pair carries the load alone (the pair's
    /// single-contact stretch): a pit, which grows near the pitch line in the stretch of
    /// single-pair contact, where the contact stress is highest (ISO 6336-2 rates pitting
    /// at the inner point of single-pair contact). A crack weakens the tooth, a broken-off
    /// share its face, over the pair's whole time in mesh.
    pub fn single_stretch_only(&self) -> bool {
        self.kind == FaultKind::Pit
    }

    /// The share of the healthy pair's stiffness and damping the faulted pair keeps;
    /// `crack(gear, share)` gives a cracked pair's (the mesh's geometry decides it).
    pub fn stiffness_factor(&self, crack: &impl Fn(FaultedGear, f64) -> f64) -> f64 {
        match self.kind {
            FaultKind::Crack => crack(self.gear, self.severity),
            FaultKind::Pit | FaultKind::Broken => 1.0 - self.severity,
        }
    }
}

/// Each tooth's stiffness factor of a gear with `teeth` teeth (1 where healthy; faults on
/// one tooth multiply); `crack` as for [`ToothFault::stiffness_factor`].
pub fn tooth_factors(
    faults: &[ToothFault],
    gear: FaultedGear,
    teeth: u32,
    crack: &impl Fn(FaultedGear, f64) -> f64,
) -> Vec<f64> {
    let mut factors = vec![1.0; teeth as usize];
    for f in faults.iter().filter(|f| f.gear == gear) {
        if let Some(slot) = factors.get_mut(f.tooth.saturating_sub(1) as usize) {
            *slot *= f.stiffness_factor(crack);
        }
    }
    factors
}
