//! The host side of `host_report`: runs the [`ToolServices`] call a report names and
//! serializes its answer as JSON, catching a panicking host.

use std::panic::{catch_unwind, AssertUnwindSafe};

use abi_stable::std_types::{RResult, RVec};
use serde::Serialize;

use super::{CtxErrorFfi, ReportFfi};
use crate::host::ToolServices;
use crate::CtxError;

fn json(value: &impl Serialize) -> Result<Vec<u8>, CtxError> {
    serde_json::to_vec(value).map_err(|e| CtxError::Encode {
        component: "host report".into(),
        message: e.to_string(),
    })
}

/// Answers `report` (with its numeric `argument`: a sequence number) as JSON.
pub fn host_report<H: ToolServices + ?Sized>(
    host: &mut H,
    report: ReportFfi,
    argument: u64,
) -> RResult<RVec<u8>, CtxErrorFfi> {
    let answer = catch_unwind(AssertUnwindSafe(|| match report {
        ReportFfi::Plugins => json(&host.plugin_infos()),
        ReportFfi::Diagnostics => json(&host.diagnostics()),
        ReportFfi::LogLines => json(&host.log_lines_since(argument)),
        ReportFfi::Scripts => json(&host.registered_scripts()),
    }));
    match answer {
        Ok(Ok(bytes)) => RResult::ROk(bytes.into()),
        Ok(Err(error)) => RResult::RErr(error.into()),
        Err(_) => {
            eprintln!("onyx: the host panicked while serving a {report:?} report to a plugin");
            RResult::RErr(
                CtxError::Invalid {
                    message: format!("the host panicked while serving `{report:?}` (a host bug)"),
                }
                .into(),
            )
        }
    }
}
