//! The `onyx` binary's log output: `tracing` to stderr for people (coloured only on a
//! terminal, never with `NO_COLOR`), and to the console ring buffer for tools (the editor's
//! Console panel).

use std::ffi::OsStr;
use std::io::IsTerminal as _;

use tracing_subscriber::layer::SubscriberExt as _;
use tracing_subscriber::util::SubscriberInitExt as _;

/// Whether log lines get ANSI colour codes: only when they go to a terminal, and not when
/// `NO_COLOR` is set to anything but empty (<https://no-color.org>). A log redirected to a
/// file or a pipe stays plain text.
pub fn use_colour(to_terminal: bool, no_color: Option<&OsStr>) -> bool {
    to_terminal && no_color.is_none_or(OsStr::is_empty)
}

/// Two warnings of winit's X11 backend that every start under Xvfb or a bare X server prints
/// and no one can act on (no XSETTINGS daemon; a screen that reports no physical size): shown
/// only when `RUST_LOG` names winit.
pub const QUIET_X11: &str = "winit::platform_impl::linux::x11::xdisplay=error,\
    winit::platform_impl::linux::x11::util::randr=error";

/// The filter for `RUST_LOG` = `rust_log` (default `info`), with [`QUIET_X11`] unless it asks
/// about winit itself.
pub fn filter_text(rust_log: Option<&str>) -> String {
    match rust_log.map(str::trim).filter(|s| !s.is_empty()) {
        Some(asked) if asked.contains("winit") => asked.to_owned(),
        Some(asked) => format!("{asked},{QUIET_X11}"),
        None => format!("info,{QUIET_X11}"),
    }
}

/// Installs the process's subscriber, filtered by `RUST_LOG` ([`filter_text`]); a `RUST_LOG`
/// that does not parse falls back to the default.
pub fn install() {
    let asked = std::env::var("RUST_LOG").ok();
    let filter = tracing_subscriber::EnvFilter::try_new(filter_text(asked.as_deref()))
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new(filter_text(None)));
    let colour = use_colour(
        std::io::stderr().is_terminal(),
        std::env::var_os("NO_COLOR").as_deref(),
    );
    tracing_subscriber::registry()
        .with(filter)
        .with(
            tracing_subscriber::fmt::layer()
                .with_writer(std::io::stderr)
                .with_ansi(colour),
        )
        .with(onyx_runtime::console::ConsoleLayer)
        .init();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_only_on_a_terminal_and_never_with_no_color() {
        assert!(use_colour(true, None));
        assert!(!use_colour(false, None), "a file or a pipe");
        assert!(!use_colour(true, Some(OsStr::new("1"))), "NO_COLOR=1");
        assert!(
            use_colour(true, Some(OsStr::new(""))),
            "an empty NO_COLOR is unset"
        );
    }

    #[test]
    fn x11_noise_is_quiet_unless_winit_is_asked_about() {
        for asked in [None, Some("warn"), Some("debug,onyx=trace")] {
            let text = filter_text(asked);
            assert!(text.contains(QUIET_X11), "{text}");
            let parsed = tracing_subscriber::EnvFilter::try_new(&text);
            assert!(parsed.is_ok(), "{text}: {parsed:?}");
        }
        assert_eq!(filter_text(Some("winit=debug")), "winit=debug");
    }
}
