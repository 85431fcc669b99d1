//! [`ConsoleLog`]: a bounded ring buffer of log lines with sequence numbers.

use std::collections::VecDeque;
use std::sync::{Mutex, OnceLock};

use onyx_plugin_api::tools::LogLine;

/// Lines the process console keeps; older ones are dropped first.
pub const CONSOLE_CAPACITY: usize = 10_000;

/// Log lines, oldest first, at most a fixed number; each gets the next sequence number.
#[derive(Debug)]
pub struct ConsoleLog {
    inner: Mutex<Lines>,
}

#[derive(Debug)]
struct Lines {
    lines: VecDeque<LogLine>,
    capacity: usize,
    next_seq: u64,
}

impl ConsoleLog {
    /// An empty log keeping at most `capacity` lines (at least one).
    pub fn new(capacity: usize) -> Self {
        Self {
            inner: Mutex::new(Lines {
                lines: VecDeque::new(),
                capacity: capacity.max(1),
                next_seq: 1,
            }),
        }
    }

    /// Appends a line; its `seq` is overwritten with the next number, which is returned.
    pub fn push(&self, mut line: LogLine) -> u64 {
        let mut inner = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        line.seq = inner.next_seq;
        inner.next_seq += 1;
        if inner.lines.len() == inner.capacity {
            inner.lines.pop_front();
        }
        inner.lines.push_back(line);
        inner.next_seq - 1
    }

    /// Copies of the lines with a sequence number above `seq`, oldest first.
    pub fn since(&self, seq: u64) -> Vec<LogLine> {
        let inner = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        let first = inner.lines.front().map_or(0, |l| l.seq);
        let skip = seq.saturating_add(1).saturating_sub(first) as usize;
        inner.lines.iter().skip(skip).cloned().collect()
    }

    /// The sequence number of the newest line (0 when empty).
    pub fn last_seq(&self) -> u64 {
        let inner = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        inner.next_seq - 1
    }
}

/// The process's console, which [`ConsoleLayer`](super::ConsoleLayer) fills.
pub fn console_log() -> &'static ConsoleLog {
    static LOG: OnceLock<ConsoleLog> = OnceLock::new();
    LOG.get_or_init(|| ConsoleLog::new(CONSOLE_CAPACITY))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(message: &str) -> LogLine {
        LogLine {
            seq: 0,
            unix_ms: 0,
            level: "INFO".into(),
            source: "test".into(),
            message: message.into(),
        }
    }

    #[test]
    fn keeps_the_newest_lines_and_reads_incrementally() {
        let log = ConsoleLog::new(3);
        for i in 0..5 {
            log.push(line(&format!("m{i}")));
        }
        let all: Vec<String> = log.since(0).into_iter().map(|l| l.message).collect();
        assert_eq!(all, ["m2", "m3", "m4"]);
        let after: Vec<u64> = log.since(4).into_iter().map(|l| l.seq).collect();
        assert_eq!(after, [5]);
        assert!(log.since(5).is_empty());
        assert_eq!(log.last_seq(), 5);
    }
}
