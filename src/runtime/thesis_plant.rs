//! The thesis's five-inertia plant (`rig::Plant`) as a scenario's run drives it.

use rig::{
    Impact, Plant, RegimeCriteria, RevolutionSample, RigError, SetPoints, SignalBlock,
    SteadySummary, SteadyWindow,
};

use super::scenario_plant::{PointWindow, ScenarioPlant};
use crate::chain::GearCondition;
use crate::vocabulary::GearIndicators;
use crate::vocabulary::frame::Frame;
use crate::vocabulary::limits::{LimitError, check_load_within, max_load_nm};

/// One block of the thesis's plant.
#[derive(Default)]
pub struct ThesisBlock {
    signals: SignalBlock,
    impacts: Vec<Impact>,
    revolutions: Vec<RevolutionSample>,
}

impl ScenarioPlant for Plant {
    type Block = ThesisBlock;
    type Window = ThesisWindow;

    fn output_step_s(&self) -> f64 {
        Plant::output_step_s(self)
    }

    fn time_s(&self) -> f64 {
        Plant::time_s(self)
    }

    fn set_points(&self) -> SetPoints {
        Plant::set_points(self)
    }

    fn check_load(&self, load_nm: f64) -> Result<(), LimitError> {
        check_load_within(load_nm, max_load_nm(self.params()), "the 1983 rig", true)
    }

    fn hold(&mut self, set: SetPoints) -> Result<(), RigError> {
        self.set_points_from_now(set)
    }

    fn block(&self) -> ThesisBlock {
        ThesisBlock::default()
    }

    fn advance(&mut self, samples: usize, block: &mut ThesisBlock) -> Result<(), RigError> {
        block.signals.clear();
        self.run(samples, &mut block.signals)?;
        block.impacts = self.drain_impacts();
        block.revolutions = self.drain_revolutions();
        Ok(())
    }

    fn impacts_in(block: &ThesisBlock) -> usize {
        block.impacts.len()
    }

    fn frame(&self, seq: u64, start: u64, block: &mut ThesisBlock) -> Frame {
        Frame::of_block(
            seq,
            start,
            &block.signals,
            std::mem::take(&mut block.impacts),
        )
    }

    fn window(&self, indicators: bool) -> ThesisWindow {
        let step_s = Plant::output_step_s(self);
        ThesisWindow {
            window: SteadyWindow::new(self.params().teeth, step_s),
            condition: indicators.then(|| GearCondition::new(1.0 / step_s)),
            teeth: self.params().teeth,
        }
    }
}

/// A window of the thesis's plant: its steady summary and the driven gear's average,
/// if taken.
pub struct ThesisWindow {
    window: SteadyWindow,
    condition: Option<GearCondition>,
    teeth: u32,
}

impl PointWindow for ThesisWindow {
    type Block = ThesisBlock;

    fn add(&mut self, block: &ThesisBlock, set: &SetPoints) {
        self.window.add_block(&block.signals, set.speed_rad_s());
        self.window.add_impacts(&block.impacts);
        self.window.add_revolutions(&block.revolutions);
        if let Some(condition) = &mut self.condition {
            condition.add(&block.signals);
        }
    }

    fn verdict(&self) -> (SteadySummary, Option<GearIndicators>) {
        let teeth = self.teeth as usize;
        let report = self.condition.as_ref().and_then(|c| c.report(teeth));
        (
            self.window.summary(&RegimeCriteria::default()),
            report.as_ref().map(GearIndicators::from),
        )
    }

    fn quick_regime(&self) -> Option<String> {
        Some(self.window.regime(&RegimeCriteria::default()).to_string())
    }

    fn judged(self) -> (String, String) {
        let regime = self.window.regime(&RegimeCriteria::default()).to_string();
        (regime, self.window.judgement().motion.to_string())
    }
}
