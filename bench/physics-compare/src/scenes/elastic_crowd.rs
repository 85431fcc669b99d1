//! Elastic crowd: 50 frictionless balls (r = 15 cm, e = 1) thrown at up to 3 m/s along each
//! axis inside a closed box of six static walls (4 m inside, e = 1), under gravity, with the
//! bounce threshold at 0 where the engine has one, for 60 s (10 s quick). Every contact is
//! elastic, so the total energy (kinetic plus potential above the floor) must stay what it
//! was: error = the largest |E(t) / E₀ − 1| over the steps. Balls land on balls lying on the
//! floor, hit two others at once and bounce off walls with others pressing on them: the
//! simultaneous impacts a single bouncing ball never has.

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const G: f32 = 9.81;
const R: f32 = 0.15;
const HALF: f32 = 2.0;
const WALL: f32 = 0.5;
const BALLS: usize = 50;

/// See the module docs.
pub struct ElasticCrowd;

struct Run {
    balls: Vec<BodyId>,
    e0: f64,
    worst: f64,
}

/// Kinetic plus potential energy above the lowest a ball can rest, J (balls do not spin:
/// nothing is rough).
fn energy(e: &dyn Engine, balls: &[BodyId]) -> f64 {
    balls
        .iter()
        .map(|&id| {
            let m = f64::from(e.mass(id));
            let p = e.position(id);
            let v = e.velocity(id);
            m * (0.5 * f64::from(v.length_squared()) + f64::from(G * (p.y + HALF - R)))
        })
        .sum()
}

/// `i`-th term of a low-discrepancy sequence in [−1, 1] (golden-ratio steps), one per
/// `axis`: the same start for every engine without a random number crate.
fn spread(i: usize, axis: usize) -> f32 {
    const STEPS: [f64; 3] = [0.618_033_988_75, 0.754_877_666_25, 0.569_840_290_99];
    let x = (0.5 + (i + 1) as f64 * STEPS[axis]).fract();
    (2.0 * x - 1.0) as f32
}

impl Scene for ElasticCrowd {
    fn name(&self) -> &'static str {
        "elastic_crowd"
    }
    fn metric(&self) -> &'static str {
        "max |E/E0 - 1|, 50 elastic balls in a closed elastic box under gravity, threshold 0"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(10.0, s),
            Size::Full => steps_for(60.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.set_restitution_threshold(0.0);
        for axis in 0..3 {
            for side in [-1.0f32, 1.0] {
                let mut half = Vec3::splat(HALF + WALL);
                half[axis] = WALL;
                let mut centre = Vec3::ZERO;
                centre[axis] = side * (HALF + WALL);
                e.add(
                    &BodySpec::fixed(ShapeSpec::Cuboid(half), centre)
                        .restitution(1.0)
                        .friction(0.0),
                );
            }
        }
        let balls = (0..BALLS)
            .map(|i| {
                let cell = Vec3::new((i % 5) as f32, ((i / 5) % 5) as f32, (i / 25) as f32);
                let jitter = Vec3::new(spread(i, 0), spread(i, 1), spread(i, 2)) * 0.05;
                let p = (cell - Vec3::new(2.0, 2.0, 0.5)) * 0.7 + jitter;
                let v = Vec3::new(spread(i + 7, 1), spread(i + 7, 2), spread(i + 7, 0)) * 3.0;
                e.add(
                    &BodySpec::dynamic(ShapeSpec::Sphere(R), p)
                        .velocity(v)
                        .restitution(1.0)
                        .friction(0.0),
                )
            })
            .collect::<Vec<_>>();
        let e0 = energy(e, &balls);
        Box::new(Run {
            balls,
            e0,
            worst: 0.0,
        })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        let change = (energy(e, &self.balls) / self.e0 - 1.0).abs();
        // NaN sticks (f64::max would drop it).
        self.worst = if change.is_nan() || self.worst.is_nan() {
            f64::NAN
        } else {
            self.worst.max(change)
        };
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        self.worst
    }
}
