//! [`StageTimer`]: time spent in each plugin per lifecycle method during one frame.

use std::collections::HashMap;
use std::time::Duration;

use onyx_plugin_api::tools::{PluginTiming, StageTiming};

use crate::stage::Stage;

/// Lifecycle methods timed (index = position in [`Stage::ALL_TIMED`]).
const STAGES: usize = Stage::ALL_TIMED.len();

/// Calls and time per plugin and stage, accumulated over one frame.
#[derive(Debug, Default)]
pub struct StageTimer {
    /// The frame being run.
    plugins: HashMap<String, [(u32, Duration); STAGES]>,
    /// The last complete frame (turned into [`PluginTiming`]s only when asked for).
    last: HashMap<String, [(u32, Duration); STAGES]>,
}

impl StageTimer {
    /// Adds one call of `stage` on `plugin` that took `elapsed`.
    pub fn record(&mut self, plugin: &str, stage: Stage, elapsed: Duration) {
        let Some(index) = Stage::ALL_TIMED.iter().position(|s| *s == stage) else {
            return;
        };
        let row = match self.plugins.get_mut(plugin) {
            Some(row) => row,
            None => self
                .plugins
                .entry(plugin.to_owned())
                .or_insert([(0, Duration::ZERO); STAGES]),
        };
        row[index].0 += 1;
        row[index].1 += elapsed;
    }

    /// Ends the frame: its figures become [`StageTimer::last`], the counters start at zero.
    /// Allocates nothing once every plugin has a row.
    pub fn end_frame(&mut self) {
        for (name, row) in &mut self.plugins {
            match self.last.get_mut(name) {
                Some(last) => *last = *row,
                None => {
                    self.last.insert(name.clone(), *row);
                }
            }
            *row = [(0, Duration::ZERO); STAGES];
        }
    }

    /// The last complete frame's figures for the plugins named in `order` (call order).
    pub fn last<'a>(&self, order: impl IntoIterator<Item = &'a str>) -> Vec<PluginTiming> {
        order
            .into_iter()
            .map(|plugin| {
                let stages = self
                    .last
                    .get(plugin)
                    .map(|row| {
                        row.iter()
                            .zip(Stage::ALL_TIMED)
                            .filter(|((calls, _), _)| *calls > 0)
                            .map(|((calls, time), stage)| StageTiming {
                                stage: stage.as_str().to_owned(),
                                calls: *calls,
                                ms: time.as_secs_f64() * 1000.0,
                            })
                            .collect()
                    })
                    .unwrap_or_default();
                PluginTiming {
                    plugin: plugin.to_owned(),
                    stages,
                }
            })
            .collect()
    }
}
