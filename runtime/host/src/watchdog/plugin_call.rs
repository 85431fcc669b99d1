//! [`PluginCall`]: which plugin, in which stage, each thread is running right now — kept
//! where a watchdog thread and a signal handler can read it.
//!
//! Each thread that calls plugins claims one record in a fixed table (released when the
//! thread ends). Entering a call stores the plugin's interned tag and the stage; leaving
//! restores what was there (calls nest: a script call inside a tool call) and bumps a counter,
//! so the watchdog can tell "the same call, still running" from "another call". Reading a
//! record takes only atomic loads: nothing allocates or locks, which a signal handler needs.

use std::cell::Cell;
use std::ptr;
use std::sync::atomic::{AtomicBool, AtomicPtr, AtomicU64, AtomicU8, Ordering};
use std::sync::Mutex;

use crate::stage::Stage;

/// What a record names: "plugin `spinner`", or "the library `…/libx.so`" while one loads.
/// Interned for the life of the process (a few bytes per distinct name), so a record can
/// point at it without owning it.
#[derive(Debug)]
pub struct CallTag {
    label: Box<str>,
}

impl CallTag {
    /// The tag of plugin `name`.
    pub fn plugin(name: &str) -> &'static CallTag {
        Self::intern(format!("plugin `{name}`"))
    }

    /// The tag of a library being opened (its static initialisers run inside the loader).
    pub fn library(path: &std::path::Path) -> &'static CallTag {
        Self::intern(format!("the library `{}`", path.display()))
    }

    /// The words that name it.
    pub fn label(&self) -> &str {
        &self.label
    }

    fn intern(label: String) -> &'static CallTag {
        static TAGS: Mutex<Vec<&'static CallTag>> = Mutex::new(Vec::new());
        let mut tags = TAGS
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(tag) = tags.iter().find(|t| *t.label == *label) {
            return tag;
        }
        let tag: &'static CallTag = Box::leak(Box::new(CallTag {
            label: label.into_boxed_str(),
        }));
        tags.push(tag);
        tag
    }
}

/// How many threads can be followed at once; a thread beyond them runs its calls unfollowed.
pub(crate) const THREADS: usize = 256;

/// One thread's current call.
pub(crate) struct CallRecord {
    claimed: AtomicBool,
    tag: AtomicPtr<CallTag>,
    stage: AtomicU8,
    /// Bumped at every entry and exit.
    seq: AtomicU64,
    /// Set by the watchdog when it reports this call: when the call was first seen, in
    /// microseconds since [`epoch`] (0: not reported).
    stuck_since_us: AtomicU64,
}

impl CallRecord {
    const fn new() -> Self {
        Self {
            claimed: AtomicBool::new(false),
            tag: AtomicPtr::new(ptr::null_mut()),
            stage: AtomicU8::new(0),
            seq: AtomicU64::new(0),
            stuck_since_us: AtomicU64::new(0),
        }
    }
}

static RECORDS: [CallRecord; THREADS] = [const { CallRecord::new() }; THREADS];

/// No record claimed yet by this thread.
const UNCLAIMED: usize = usize::MAX;
/// The table was full when this thread first called a plugin.
const UNFOLLOWED: usize = usize::MAX - 1;

thread_local! {
    /// This thread's record. Plain `Cell`, constant-initialised, no destructor: readable from a
    /// signal handler.
    static INDEX: Cell<usize> = const { Cell::new(UNCLAIMED) };
    /// Frees the record when the thread ends.
    static RELEASE: Release = const { Release };
}

struct Release;

impl Drop for Release {
    fn drop(&mut self) {
        let index = INDEX.with(Cell::get);
        let Some(record) = RECORDS.get(index) else {
            return;
        };
        if !record.tag.load(Ordering::Acquire).is_null() {
            // The thread ends inside a plugin call: `exit` (glibc runs thread-local
            // destructors before the `atexit` hooks, which still need to see the call) or a
            // thread killed mid-call. Keep the record; it is one of many.
            return;
        }
        INDEX.with(|i| i.set(UNFOLLOWED));
        record.claimed.store(false, Ordering::Release);
    }
}

fn this_thread() -> Option<&'static CallRecord> {
    let index = INDEX.with(Cell::get);
    if index != UNCLAIMED {
        return RECORDS.get(index);
    }
    let claimed = RECORDS.iter().position(|r| {
        r.claimed
            .compare_exchange(false, true, Ordering::AcqRel, Ordering::Relaxed)
            .is_ok()
    });
    let index = claimed.unwrap_or(UNFOLLOWED);
    INDEX.with(|i| i.set(index));
    if claimed.is_some() {
        // Registers the destructor that gives the record back.
        RELEASE.with(|_| {});
    }
    RECORDS.get(index)
}

/// Marks the current thread as running `stage` of `tag` until dropped.
#[must_use = "the call is marked only while the guard lives"]
pub(crate) struct PluginCall {
    record: Option<&'static CallRecord>,
    previous_tag: *mut CallTag,
    previous_stage: u8,
}

impl PluginCall {
    /// Marks the call.
    pub(crate) fn enter(tag: &'static CallTag, stage: Stage) -> Self {
        let Some(record) = this_thread() else {
            return Self {
                record: None,
                previous_tag: ptr::null_mut(),
                previous_stage: 0,
            };
        };
        let previous_tag = record.tag.load(Ordering::Relaxed);
        let previous_stage = record.stage.load(Ordering::Relaxed);
        record.stage.store(stage as u8, Ordering::Relaxed);
        record
            .tag
            .store(ptr::from_ref(tag).cast_mut(), Ordering::Relaxed);
        bump(record);
        Self {
            record: Some(record),
            previous_tag,
            previous_stage,
        }
    }
}

impl Drop for PluginCall {
    fn drop(&mut self) {
        if let Some(record) = self.record {
            // Reported stuck: say it returned, here, before the process can end.
            if record.stuck_since_us.load(Ordering::Acquire) != 0 {
                let since = record.stuck_since_us.swap(0, Ordering::AcqRel);
                if let (true, Some(call)) = (since != 0, current()) {
                    super::watchdog_thread::returned(&call, since_epoch_us() - since);
                }
            }
            record.stage.store(self.previous_stage, Ordering::Relaxed);
            record.tag.store(self.previous_tag, Ordering::Relaxed);
            bump(record);
        }
    }
}

/// The instant [`since_epoch_us`] counts from (the first time anything asks).
fn epoch() -> std::time::Instant {
    static EPOCH: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();
    *EPOCH.get_or_init(std::time::Instant::now)
}

/// Microseconds since [`epoch`], at least 1.
pub(crate) fn since_epoch_us() -> u64 {
    u64::try_from(epoch().elapsed().as_micros())
        .unwrap_or(u64::MAX)
        .max(1)
}

/// Notes that the call seen in record `index` as `seq` is reported stuck, first seen at
/// `since_us` ([`since_epoch_us`]), so the call's own thread reports its return. `false` if
/// the call returned meanwhile (nothing is noted then).
pub(crate) fn mark_stuck(index: usize, seq: u64, since_us: u64) -> bool {
    let Some(record) = RECORDS.get(index) else {
        return false;
    };
    record.stuck_since_us.store(since_us, Ordering::Release);
    if record.seq.load(Ordering::Acquire) == seq {
        return true;
    }
    // It returned meanwhile: take the mark back (its thread may have taken it already).
    record.stuck_since_us.swap(0, Ordering::AcqRel);
    false
}

/// Takes back the stuck mark of record `index` if its call ended without seeing it (it
/// returned between the watchdog's look and its mark): `Some(first seen)` then.
pub(crate) fn take_stuck(index: usize) -> Option<u64> {
    let record = RECORDS.get(index)?;
    match record.stuck_since_us.swap(0, Ordering::AcqRel) {
        0 => None,
        since => Some(since),
    }
}

/// Only the owning thread writes a record: a load and a store make the increment.
fn bump(record: &CallRecord) {
    let next = record.seq.load(Ordering::Relaxed).wrapping_add(1);
    record.seq.store(next, Ordering::Release);
}

/// A call seen in a record.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SeenCall {
    pub tag: &'static CallTag,
    pub stage: Stage,
    /// Which entry or exit this is; equal in two looks means the same call is still running.
    pub seq: u64,
}

/// The call the record at `index` shows, if any. Lock-free and allocation-free.
pub(crate) fn seen(index: usize) -> Option<SeenCall> {
    let record = RECORDS.get(index)?;
    if !record.claimed.load(Ordering::Acquire) {
        return None;
    }
    let seq = record.seq.load(Ordering::Acquire);
    let tag = record.tag.load(Ordering::Acquire);
    let stage = record.stage.load(Ordering::Relaxed);
    // SAFETY: a non-null tag points at a leaked, never freed `CallTag`.
    let tag = unsafe { tag.cast_const().as_ref() }?;
    Some(SeenCall {
        tag,
        stage: Stage::from_index(stage)?,
        seq,
    })
}

/// The call the current thread is in, if any. Async-signal-safe: a thread-local read and
/// atomic loads.
pub(crate) fn current() -> Option<SeenCall> {
    let index = INDEX.with(Cell::get);
    seen(index)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether the current thread has a record (calls on it are followed).
    fn followed() -> bool {
        INDEX.with(Cell::get) < THREADS
    }

    #[test]
    fn calls_nest_and_unwind() {
        let outer = CallTag::plugin("outer-test");
        let inner = CallTag::plugin("inner-test");
        assert!(current().is_none());
        {
            let _a = PluginCall::enter(outer, Stage::Update);
            assert!(followed());
            let first = current().expect("in a call");
            assert_eq!(first.tag.label(), "plugin `outer-test`");
            assert_eq!(first.stage, Stage::Update);
            {
                let _b = PluginCall::enter(inner, Stage::Script);
                let nested = current().expect("in a call");
                assert_eq!(nested.tag.label(), "plugin `inner-test`");
                assert_eq!(nested.stage, Stage::Script);
            }
            let back = current().expect("back in the outer call");
            assert_eq!(back.tag.label(), "plugin `outer-test`");
            assert_ne!(back.seq, first.seq, "leaving the inner call is a new look");
        }
        assert!(current().is_none());
    }

    #[test]
    fn a_stuck_mark_is_taken_by_the_return_or_refused_after_it() {
        let tag = CallTag::plugin("stuck-test");
        let call = PluginCall::enter(tag, Stage::Render);
        let index = INDEX.with(Cell::get);
        let look = seen(index).expect("in a call");
        assert!(mark_stuck(index, look.seq, since_epoch_us()));
        drop(call); // reports the return and takes the mark
        assert_eq!(take_stuck(index), None);
        // A look from before the return is refused.
        assert!(!mark_stuck(index, look.seq, since_epoch_us()));
        assert_eq!(take_stuck(index), None);
    }

    #[test]
    fn tags_are_interned() {
        assert!(std::ptr::eq(
            CallTag::plugin("same"),
            CallTag::plugin("same")
        ));
    }

    #[test]
    fn records_are_given_back_when_threads_end() {
        let claimed = || {
            RECORDS
                .iter()
                .filter(|r| r.claimed.load(Ordering::Acquire))
                .count()
        };
        for _ in 0..(THREADS + 8) {
            std::thread::spawn(|| {
                let _call = PluginCall::enter(CallTag::plugin("short-lived"), Stage::Update);
                assert!(followed(), "a record was free");
            })
            .join()
            .expect("thread ran");
        }
        // Other tests run threads too; what matters is that these did not use the table up.
        assert!(claimed() < THREADS);
    }
}
