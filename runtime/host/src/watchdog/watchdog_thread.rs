//! [`start`]: a thread that reports plugin calls running longer than a limit.
//!
//! Native code cannot be stopped safely from outside: killing a thread mid-call would leave
//! locks held and the world half-written. So the watchdog only reports — which plugin, which
//! stage, for how long — once when the limit passes, again every [`WatchdogSettings::repeat`]
//! while the call lasts, and once more when it returns. The host waits; the user can attach a
//! debugger (the watchdog then stays quiet) or end the process.

use std::sync::{Arc, Mutex, OnceLock};
use std::time::Duration;

use super::plugin_call::{mark_stuck, seen, since_epoch_us, take_stuck, SeenCall, THREADS};

/// When the watchdog speaks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WatchdogSettings {
    /// A call running this long is reported.
    pub limit: Duration,
    /// While it goes on, it is reported again this often.
    pub repeat: Duration,
}

/// The default limit: long enough for a first frame's shader compile or a big scene load.
pub const DEFAULT_WATCHDOG_LIMIT: Duration = Duration::from_secs(5);

impl Default for WatchdogSettings {
    fn default() -> Self {
        Self {
            limit: DEFAULT_WATCHDOG_LIMIT,
            repeat: Duration::from_secs(10),
        }
    }
}

/// Where a stuck call is shown besides the log: `Some(sentence)` while one is stuck, `None`
/// when none is any more (the window's title, set by the windowed runner).
pub type StuckSink = Arc<dyn Fn(Option<&str>) + Send + Sync>;

struct Shared {
    settings: Mutex<WatchdogSettings>,
    sink: Mutex<Option<StuckSink>>,
}

static WATCHDOG: OnceLock<Shared> = OnceLock::new();

/// Starts the process's watchdog (or changes its settings if it runs). It follows every
/// thread that calls plugins, for the rest of the process.
pub fn start(settings: WatchdogSettings) {
    let mut started = false;
    let shared = WATCHDOG.get_or_init(|| {
        started = true;
        Shared {
            settings: Mutex::new(settings),
            sink: Mutex::new(None),
        }
    });
    *lock(&shared.settings) = settings;
    if started {
        let spawned = std::thread::Builder::new()
            .name("onyx watchdog".into())
            .spawn(move || watch(shared));
        if let Err(error) = spawned {
            tracing::warn!("cannot start the watchdog thread: {error}; long calls go unreported");
        }
    }
}

/// Sets (or clears) where stuck calls are shown besides the log.
pub fn set_stuck_sink(sink: Option<StuckSink>) {
    if let Some(shared) = WATCHDOG.get() {
        *lock(&shared.sink) = sink;
    }
}

fn lock<T>(mutex: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    mutex
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// A call the watchdog is timing.
#[derive(Clone, Copy)]
struct Timed {
    call: SeenCall,
    /// When the watchdog first saw it ([`since_epoch_us`]).
    since_us: u64,
    /// When it was last reported, if it passed the limit.
    reported_us: Option<u64>,
}

fn watch(shared: &'static Shared) {
    let mut timed: Vec<Option<Timed>> = vec![None; THREADS];
    loop {
        let settings = *lock(&shared.settings);
        std::thread::sleep(
            (settings.limit / 8).clamp(Duration::from_millis(10), Duration::from_millis(250)),
        );
        let limit_us = micros(settings.limit);
        let repeat_us = micros(settings.repeat);
        for (index, slot) in timed.iter_mut().enumerate() {
            let call = seen(index);
            let same = matches!((&call, slot.as_ref()), (Some(c), Some(t)) if c.seq == t.call.seq);
            if !same {
                if let Some(ended) = slot.take().filter(|t| t.reported_us.is_some()) {
                    // Normally the call's thread reports its return; if the mark was left
                    // behind (it returned as the mark was set), do it here.
                    if let Some(since) = take_stuck(index) {
                        returned(&ended.call, since_epoch_us().saturating_sub(since));
                    }
                }
                *slot = call.map(|call| Timed {
                    call,
                    since_us: since_epoch_us(),
                    reported_us: None,
                });
                continue;
            }
            let Some(t) = slot.as_mut() else { continue };
            let now = since_epoch_us();
            let due = match t.reported_us {
                None => now - t.since_us >= limit_us,
                Some(at) => now - at >= repeat_us,
            };
            if !due || debugger_attached() {
                continue;
            }
            if t.reported_us.is_none() && !mark_stuck(index, t.call.seq, t.since_us) {
                continue; // it just returned
            }
            let sentence = format!(
                "{} has been running {} for {:.1} s",
                t.call.tag.label(),
                t.call.stage,
                (now - t.since_us) as f64 / 1e6
            );
            if t.reported_us.is_none() {
                tracing::warn!(
                    "{sentence} (the watchdog limit is {:.1} s); the host waits for it: native \
                     code cannot be stopped safely. Attach a debugger to see where it is, or end \
                     the process",
                    settings.limit.as_secs_f64()
                );
            } else {
                tracing::warn!("{sentence}; still waiting");
            }
            t.reported_us = Some(now);
            show(Some(&sentence));
        }
    }
}

fn micros(duration: Duration) -> u64 {
    u64::try_from(duration.as_micros()).unwrap_or(u64::MAX)
}

/// A call reported stuck has returned after `running_us`: said on the thread that returns
/// (so it is said before that thread can end the process) or by the watchdog.
pub(crate) fn returned(call: &SeenCall, running_us: u64) {
    tracing::info!(
        "{} returned from {} after {:.1} s",
        call.tag.label(),
        call.stage,
        running_us as f64 / 1e6
    );
    show(None);
}

fn show(sentence: Option<&str>) {
    let Some(shared) = WATCHDOG.get() else { return };
    let sink = lock(&shared.sink).clone();
    if let Some(sink) = sink {
        sink(sentence);
    }
}

/// Whether a debugger (any tracer) is attached to this process. Linux reads `TracerPid` in
/// `/proc/self/status`; elsewhere this is `false`.
pub fn debugger_attached() -> bool {
    let Ok(status) = std::fs::read_to_string("/proc/self/status") else {
        return false;
    };
    status
        .lines()
        .find_map(|l| l.strip_prefix("TracerPid:"))
        .is_some_and(|pid| pid.trim() != "0")
}
