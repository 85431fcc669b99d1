//! [`AnimationClip`]: keyframed translation, rotation and scale channels, sampled at any time
//! (step, linear with slerp for rotations, cubic-spline Hermite as glTF defines them).

use onyx_plugin_api::glam::{Quat, Vec3, Vec4};

/// Which part of a [`Transform`](onyx_plugin_api::Transform) a channel drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Property {
    /// `translation`, metres.
    Translation,
    /// `rotation`, a unit quaternion (x, y, z, w).
    Rotation,
    /// `scale`.
    Scale,
}

/// How values between two keys are found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// The earlier key's value until the next key.
    Step,
    /// Straight lines (rotations: spherical, the shorter way).
    Linear,
    /// Hermite curves through the keys with the file's in and out tangents.
    CubicSpline,
}

/// Keys of one channel: strictly increasing times and their values (for
/// [`Interpolation::CubicSpline`], three per key: in-tangent, value, out-tangent).
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// How values between keys are found.
    pub interpolation: Interpolation,
    /// Key times, seconds, strictly increasing.
    pub times: Vec<f32>,
    /// Values (xyz in the first three lanes for translation and scale).
    pub values: Vec<Vec4>,
}

/// Why a curve cannot be sampled.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CurveError {
    /// No keys.
    #[error("it has no keys")]
    Empty,
    /// A time or value is NaN or infinite, or times do not increase.
    #[error("its key times are not finite and strictly increasing")]
    Times,
    /// Values and keys do not match in number.
    #[error("it has {values} values for {keys} keys ({per_key} per key expected)")]
    Count {
        /// Values given.
        values: usize,
        /// Keys given.
        keys: usize,
        /// Values each key needs.
        per_key: usize,
    },
}

impl Curve {
    /// A curve, checked: keys present, times finite and strictly increasing, values finite
    /// and as many as the interpolation needs.
    pub fn new(
        interpolation: Interpolation,
        times: Vec<f32>,
        values: Vec<Vec4>,
    ) -> Result<Self, CurveError> {
        if times.is_empty() {
            return Err(CurveError::Empty);
        }
        if times.iter().any(|t| !t.is_finite()) || times.windows(2).any(|w| w[1] <= w[0]) {
            return Err(CurveError::Times);
        }
        let per_key = if interpolation == Interpolation::CubicSpline {
            3
        } else {
            1
        };
        if values.len() != times.len() * per_key || values.iter().any(|v| !v.is_finite()) {
            return Err(CurveError::Count {
                values: values.len(),
                keys: times.len(),
                per_key,
            });
        }
        Ok(Self {
            interpolation,
            times,
            values,
        })
    }

    /// The last key's time, seconds.
    pub fn end(&self) -> f32 {
        self.times.last().copied().unwrap_or(0.0)
    }

    /// The value of key `i`.
    fn key(&self, i: usize) -> Vec4 {
        match self.interpolation {
            Interpolation::CubicSpline => self.values[3 * i + 1],
            _ => self.values[i],
        }
    }

    /// The value at `time` seconds: the first key's before it, the last key's after it.
    /// Rotations (`rotation`) are slerped and normalised.
    pub fn sample(&self, time: f32, rotation: bool) -> Vec4 {
        let next = self.times.partition_point(|&t| t <= time);
        if next == 0 {
            return self.key(0);
        }
        if next == self.times.len() {
            return self.key(next - 1);
        }
        let i = next - 1;
        let (t0, t1) = (self.times[i], self.times[next]);
        let span = t1 - t0;
        let s = (time - t0) / span;
        match self.interpolation {
            Interpolation::Step => self.key(i),
            Interpolation::Linear if rotation => {
                let a = Quat::from_vec4(self.key(i));
                let b = Quat::from_vec4(self.key(next));
                Vec4::from(a.slerp(b, s))
            }
            Interpolation::Linear => self.key(i).lerp(self.key(next), s),
            Interpolation::CubicSpline => {
                let p0 = self.values[3 * i + 1];
                let m0 = self.values[3 * i + 2] * span;
                let p1 = self.values[3 * next + 1];
                let m1 = self.values[3 * next] * span;
                let (s2, s3) = (s * s, s * s * s);
                let v = p0 * (2.0 * s3 - 3.0 * s2 + 1.0)
                    + m0 * (s3 - 2.0 * s2 + s)
                    + p1 * (-2.0 * s3 + 3.0 * s2)
                    + m1 * (s3 - s2);
                if rotation {
                    v.normalize_or(Vec4::W)
                } else {
                    v
                }
            }
        }
    }
}

/// One animated property of one entity, found by the names from the animator's entity down.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// Names from the animator's entity (excluded) down to the target.
    pub target: Vec<String>,
    /// What it drives.
    pub property: Property,
    /// Its keys.
    pub curve: Curve,
}

/// A set of channels played together.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AnimationClip {
    /// The channels.
    pub channels: Vec<Channel>,
    /// The last key time of any channel, seconds.
    pub duration: f32,
}

impl Channel {
    /// The translation or scale at `time` (the first three lanes).
    pub fn vec3_at(&self, time: f32) -> Vec3 {
        self.curve.sample(time, false).truncate()
    }

    /// The rotation at `time`.
    pub fn rotation_at(&self, time: f32) -> Quat {
        Quat::from_vec4(self.curve.sample(time, true)).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32) -> Vec4 {
        Vec4::new(x, 0.0, 0.0, 0.0)
    }

    #[test]
    fn step_holds_linear_interpolates_and_ends_clamp() {
        let step = Curve::new(Interpolation::Step, vec![0.0, 1.0], vec![v(2.0), v(4.0)])
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(step.sample(0.99, false).x, 2.0);
        assert_eq!(step.sample(1.0, false).x, 4.0);
        let linear = Curve::new(Interpolation::Linear, vec![1.0, 3.0], vec![v(2.0), v(4.0)])
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(linear.sample(2.0, false).x, 3.0);
        assert_eq!(linear.sample(-5.0, false).x, 2.0);
        assert_eq!(linear.sample(9.0, false).x, 4.0);
    }

    #[test]
    fn cubic_spline_with_zero_tangents_is_smoothstep() {
        // In-tangent, value, out-tangent per key.
        let cubic = Curve::new(
            Interpolation::CubicSpline,
            vec![0.0, 2.0],
            vec![v(0.0), v(0.0), v(0.0), v(0.0), v(1.0), v(0.0)],
        )
        .unwrap_or_else(|e| panic!("{e}"));
        for s in [0.25f32, 0.5, 0.75] {
            let expected = 3.0 * s * s - 2.0 * s * s * s;
            let got = cubic.sample(2.0 * s, false).x;
            assert!((got - expected).abs() < 1e-6, "s={s}: {got} != {expected}");
        }
        // A tangent of 1 unit/s over a 2 s span with equal values bulges by span/4 · m at s=½.
        let bulge = Curve::new(
            Interpolation::CubicSpline,
            vec![0.0, 2.0],
            vec![v(0.0), v(0.0), v(1.0), v(0.0), v(0.0), v(0.0)],
        )
        .unwrap_or_else(|e| panic!("{e}"));
        assert!((bulge.sample(1.0, false).x - 0.25).abs() < 1e-6);
    }

    #[test]
    fn linear_rotation_is_a_slerp() {
        let a = Quat::IDENTITY;
        let b = Quat::from_rotation_y(std::f32::consts::FRAC_PI_2);
        let curve = Curve::new(
            Interpolation::Linear,
            vec![0.0, 1.0],
            vec![Vec4::from(a), Vec4::from(b)],
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let half = Quat::from_vec4(curve.sample(0.5, true));
        let expected = Quat::from_rotation_y(std::f32::consts::FRAC_PI_4);
        assert!(half.abs_diff_eq(expected, 1e-6), "{half} != {expected}");
    }

    #[test]
    fn bad_keys_are_refused() {
        assert_eq!(
            Curve::new(Interpolation::Linear, vec![], vec![]),
            Err(CurveError::Empty)
        );
        assert_eq!(
            Curve::new(Interpolation::Linear, vec![1.0, 1.0], vec![v(0.0), v(1.0)]),
            Err(CurveError::Times)
        );
        assert!(matches!(
            Curve::new(Interpolation::CubicSpline, vec![0.0], vec![v(0.0)]),
            Err(CurveError::Count { per_key: 3, .. })
        ));
    }
}
