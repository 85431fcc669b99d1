//! [`PairHasher`]: a fast multiplicative hasher for `u64` pair keys.

use std::hash::{BuildHasherDefault, Hasher};

/// Multiplicative (Fibonacci) hasher for the narrowphase pair map; keys are packed collider
/// indices, not attacker-controlled, so DoS resistance is not needed.
#[derive(Clone, Copy, Debug, Default)]
pub struct PairHasher(u64);

impl Hasher for PairHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0.rotate_left(8) ^ u64::from(b)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        }
    }

    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0 ^ v).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        self.0 ^= self.0 >> 29;
    }
}

/// Builder for [`PairHasher`].
pub type BuildPairHasher = BuildHasherDefault<PairHasher>;
