//! [`install_crash_report`]: one line naming the plugin and stage when the process dies of a
//! native failure, and a distinct exit status.
//!
//! A segfault, a bus error, an illegal instruction, a trap outside a debugger, an abort (a plugin built with
//! `panic = "abort"`, a failed C assertion, a double panic) or a stack overflow cannot be
//! caught: the process is going down. The handler writes one line with `write(2)` only —
//! async-signal-safe, no allocation, no lock — and ends the process with
//! [`EXIT_NATIVE_CRASH`]. A plugin calling `exit` (Rust's `std::process::exit`) during a call
//! is caught by an `atexit` hook, which says so and ends with [`EXIT_PLUGIN_EXITED`].
//!
//! Raw `sigaction` through `libc`: `signal-hook`, the well-kept crate for signals, refuses
//! SIGSEGV, SIGBUS, SIGILL and SIGFPE on purpose (its handlers may run arbitrary code), and
//! these are exactly the signals this handler exists for.

use super::plugin_call::{current, seen, SeenCall, THREADS};

/// The exit status after a native crash (documented in `onyx --help`).
pub const EXIT_NATIVE_CRASH: u8 = 3;
/// The exit status when a plugin ended the process itself during a call.
pub const EXIT_PLUGIN_EXITED: u8 = 4;

/// Installs the crash handlers for the rest of the process. Call once, early, from the
/// binary that owns the process (not from a library embedding the host: its own handlers
/// would be replaced).
pub fn install_crash_report() {
    #[cfg(unix)]
    unix::install();
}

/// A fixed buffer a signal handler can format a line into.
struct Line {
    bytes: [u8; 1024],
    len: usize,
}

impl Line {
    const fn new() -> Self {
        Self {
            bytes: [0; 1024],
            len: 0,
        }
    }

    fn push(&mut self, text: &str) -> &mut Self {
        let room = self.bytes.len() - self.len;
        let n = text.len().min(room);
        self.bytes[self.len..self.len + n].copy_from_slice(&text.as_bytes()[..n]);
        self.len += n;
        self
    }

    fn push_number(&mut self, mut n: u32) -> &mut Self {
        let mut digits = [0u8; 10];
        let mut i = digits.len();
        loop {
            i -= 1;
            digits[i] = b'0' + (n % 10) as u8;
            n /= 10;
            if n == 0 {
                break;
            }
        }
        let text = std::str::from_utf8(&digits[i..]).unwrap_or("?");
        self.push(text)
    }

    fn as_bytes(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

/// Where the crash happened: the crashing thread's call, else "the host" and any plugin call
/// running on another thread.
fn push_place(line: &mut Line) {
    fn call(line: &mut Line, call: &SeenCall) {
        line.push(call.tag.label())
            .push(" (")
            .push(call.stage.as_str())
            .push(")");
    }
    if let Some(here) = current() {
        line.push("in ");
        call(line, &here);
        return;
    }
    line.push("in the host, outside any plugin call");
    if let Some(elsewhere) = (0..THREADS).find_map(seen) {
        line.push(", while ");
        call(line, &elsewhere);
        line.push(" was running on another thread");
    }
}

/// The line for a fatal `signal`, e.g. `SIGSEGV (a bad memory access or a stack overflow)`.
fn crash_line(line: &mut Line, signal_words: &str) {
    line.push("onyx: native crash: ")
        .push(signal_words)
        .push(" ");
    push_place(line);
    line.push("; the process ends with status ")
        .push_number(u32::from(EXIT_NATIVE_CRASH))
        .push("\n");
}

#[cfg(unix)]
mod unix {
    use std::sync::atomic::{AtomicBool, Ordering};

    use super::{crash_line, current, push_place, Line, EXIT_NATIVE_CRASH, EXIT_PLUGIN_EXITED};

    const SIGNALS: [(libc::c_int, &str); 6] = [
        (
            libc::SIGSEGV,
            "SIGSEGV (a bad memory access or a stack overflow)",
        ),
        (
            libc::SIGBUS,
            "SIGBUS (a bad memory access: a misaligned or unmapped address)",
        ),
        (libc::SIGILL, "SIGILL (an illegal instruction)"),
        (
            libc::SIGABRT,
            "SIGABRT (an abort: a panic in code built with panic = \"abort\", a panic while \
             panicking, or a failed native assertion)",
        ),
        (libc::SIGFPE, "SIGFPE (an arithmetic fault)"),
        (
            libc::SIGTRAP,
            "SIGTRAP (a trap instruction outside a debugger: a breakpoint left in, or a failed \
             runtime check)",
        ),
    ];

    /// Set by the first fatal signal: a second one (the handler's own fault, another thread)
    /// only ends the process.
    static REPORTED: AtomicBool = AtomicBool::new(false);

    fn write_stderr(bytes: &[u8]) {
        let mut rest = bytes;
        while !rest.is_empty() {
            // SAFETY: write(2) on fd 2 with a valid buffer; async-signal-safe.
            let n = unsafe { libc::write(2, rest.as_ptr().cast(), rest.len()) };
            if n <= 0 {
                return;
            }
            rest = &rest[n.unsigned_abs()..];
        }
    }

    extern "C" fn on_fatal_signal(
        signal: libc::c_int,
        _info: *mut libc::siginfo_t,
        _context: *mut libc::c_void,
    ) {
        if !REPORTED.swap(true, Ordering::SeqCst) {
            let words = SIGNALS
                .iter()
                .find(|(s, _)| *s == signal)
                .map_or("a fatal signal", |(_, words)| words);
            let mut line = Line::new();
            crash_line(&mut line, words);
            write_stderr(line.as_bytes());
        }
        // SAFETY: _exit is async-signal-safe and ends the process at once.
        unsafe { libc::_exit(i32::from(EXIT_NATIVE_CRASH)) }
    }

    extern "C" fn on_exit() {
        if current().is_none() || REPORTED.swap(true, Ordering::SeqCst) {
            return; // a normal exit, or one after a crash report
        }
        let mut line = Line::new();
        line.push("onyx: the process was ended by a call to exit ");
        push_place(&mut line);
        line.push(
            "; the host did not finish (nothing was saved or dumped); the process ends with \
             status ",
        )
        .push_number(u32::from(EXIT_PLUGIN_EXITED))
        .push("\n");
        write_stderr(line.as_bytes());
        // SAFETY: leaving from an atexit hook without running the others: the host's state
        // is mid-call and must not be torn down as if the run had finished.
        unsafe { libc::_exit(i32::from(EXIT_PLUGIN_EXITED)) }
    }

    pub(super) fn install() {
        // The alternate stack a handler needs to run after a stack overflow: Rust's runtime
        // gives one to the main thread and to every thread it spawns; give this thread one
        // if it has none (an embedding that started the host elsewhere).
        ensure_alternate_stack();
        for (signal, _) in SIGNALS {
            // SAFETY: a zeroed sigaction is a valid starting point; the handler only makes
            // async-signal-safe calls.
            unsafe {
                let mut action: libc::sigaction = std::mem::zeroed();
                action.sa_sigaction = on_fatal_signal as *const () as usize;
                action.sa_flags = libc::SA_SIGINFO | libc::SA_ONSTACK;
                libc::sigemptyset(&mut action.sa_mask);
                if libc::sigaction(signal, &action, std::ptr::null_mut()) != 0 {
                    tracing::debug!(signal, "cannot install the crash handler");
                }
            }
        }
        // SAFETY: registers a plain extern "C" function.
        if unsafe { libc::atexit(on_exit) } != 0 {
            tracing::debug!("cannot register the exit hook");
        }
    }

    fn ensure_alternate_stack() {
        // SAFETY: querying and setting this thread's signal stack with valid pointers; the
        // new stack is leaked on purpose (it must outlive the thread's use of signals).
        unsafe {
            let mut current: libc::stack_t = std::mem::zeroed();
            if libc::sigaltstack(std::ptr::null(), &mut current) != 0 {
                return;
            }
            if current.ss_flags & libc::SS_DISABLE == 0 {
                return; // there is one
            }
            let size = 64 * 1024;
            let memory = Box::leak(vec![0u8; size].into_boxed_slice());
            let stack = libc::stack_t {
                ss_sp: memory.as_mut_ptr().cast(),
                ss_flags: 0,
                ss_size: size,
            };
            libc::sigaltstack(&stack, std::ptr::null_mut());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::plugin_call::{CallTag, PluginCall};
    use super::*;
    use crate::stage::Stage;

    fn text(line: &Line) -> String {
        String::from_utf8_lossy(line.as_bytes()).into_owned()
    }

    #[test]
    fn the_line_names_the_plugin_and_stage() {
        let _call = PluginCall::enter(CallTag::plugin("crashy"), Stage::FixedUpdate);
        let mut line = Line::new();
        crash_line(
            &mut line,
            "SIGSEGV (a bad memory access or a stack overflow)",
        );
        assert_eq!(
            text(&line),
            "onyx: native crash: SIGSEGV (a bad memory access or a stack overflow) in plugin \
             `crashy` (on_fixed_update); the process ends with status 3\n"
        );
    }

    #[test]
    fn outside_a_call_it_is_the_host() {
        let mut line = Line::new();
        crash_line(&mut line, "SIGILL (an illegal instruction)");
        assert!(
            text(&line).starts_with(
                "onyx: native crash: SIGILL (an illegal instruction) in the host, outside any \
                 plugin call"
            ),
            "{}",
            text(&line)
        );
    }

    #[test]
    fn a_long_line_is_cut_not_overrun() {
        let mut line = Line::new();
        for _ in 0..100 {
            line.push("0123456789abcdef");
        }
        assert_eq!(line.as_bytes().len(), 1024);
        let mut n = Line::new();
        n.push_number(0).push(" ").push_number(u32::MAX);
        assert_eq!(text(&n), "0 4294967295");
    }
}
