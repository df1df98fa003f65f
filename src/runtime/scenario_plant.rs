//! What the plant's thread needs of a plant, whichever it is: the thesis's five-inertia
//! plant (`thesis_plant.rs`) or a rig file's (`rig_file_plant.rs`). Each advances block by
//! block under set points that commands change, hands the chain a frame of its signals,
//! and judges a window of its blocks.

use rig::{RigError, SetPoints, SteadySummary};

use crate::vocabulary::GearIndicators;
use crate::vocabulary::frame::Frame;
use crate::vocabulary::limits::LimitError;

/// A plant a scenario's run advances.
pub trait ScenarioPlant: Send {
    /// One block of the plant's output: its signals, impacts and revolutions.
    type Block: Send;
    /// A window of blocks whose motion is judged.
    type Window: PointWindow<Block = Self::Block>;

    /// Time between output samples (s).
    fn output_step_s(&self) -> f64;
    /// Simulated time now (s).
    fn time_s(&self) -> f64;
    /// The set points now.
    fn set_points(&self) -> SetPoints;
    /// Whether the motor holds a brake load of `load_nm` (N m).
    fn check_load(&self, load_nm: f64) -> Result<(), LimitError>;
    /// Holds `set` from the next sample on.
    fn hold(&mut self, set: SetPoints) -> Result<(), RigError>;
    /// An empty block, shaped for this plant's signals.
    fn block(&self) -> Self::Block;
    /// Advances `samples` samples into `block` (cleared first).
    fn advance(&mut self, samples: usize, block: &mut Self::Block) -> Result<(), RigError>;
    /// Contacts that started in `block`.
    fn impacts_in(block: &Self::Block) -> usize;
    /// The frame of `block` (sequence `seq`, from sample `start`); its impacts are moved
    /// into the frame.
    fn frame(&self, seq: u64, start: u64, block: &mut Self::Block) -> Frame;
    /// An empty window; with `indicators`, it also averages the watched gear's
    /// revolutions for its condition indicators (a point's window; the live regime's
    /// needs none).
    fn window(&self, indicators: bool) -> Self::Window;
}

/// A window of a plant's blocks, summed up and judged as a point's verdict.
pub trait PointWindow: Send + 'static {
    /// The plant's block.
    type Block;

    /// Adds a block made under `set`.
    fn add(&mut self, block: &Self::Block, set: &SetPoints);
    /// The window summed up and its motion judged, and the watched gear's indicators
    /// (none under two revolutions).
    fn verdict(&self) -> (SteadySummary, Option<GearIndicators>);
    /// The regime, where the plant tells it without the judge (cheap, in the plant's
    /// thread).
    fn quick_regime(&self) -> Option<String>;
    /// The regime and the judged motion (a spectrum of the window: costly).
    fn judged(self) -> (String, String);
}
