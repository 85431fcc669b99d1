//! [`AttachInfoFfi`]: [`AttachInfo`](crate::AttachInfo) borrowed as plain data.

use abi_stable::{
    std_types::{RSlice, RStr, Tuple2},
    StableAbi,
};

#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug)]
pub struct AttachInfoFfi<'a> {
    pub reload: bool,
    pub settings: RSlice<'a, Tuple2<RStr<'a>, RStr<'a>>>,
}
