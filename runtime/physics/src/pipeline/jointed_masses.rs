//! [`JointedMasses`]: the mass of each awake body's group of bodies held together by joints,
//! for the damping of the contacts they rest on (see the solve stage): a jointed group moves
//! as one body (a ragdoll on the ground rings on its contacts with all its mass), bodies
//! merely resting on each other hang on soft contacts of their own and do not.

use crate::pipeline::union_find::UnionFind;
use crate::solver::body_state::BodyState;

/// Per solver body, the mass of its jointed group; empty when the step joins no bodies
/// (each body is then its own group).
#[derive(Debug, Default)]
pub(crate) struct JointedMasses {
    group: Vec<f32>,
}

impl JointedMasses {
    /// Groups `states` (solver bodies) along `links`, pairs of solver indices joined by a
    /// joint (only joints between two dynamic bodies: one to a static or kinematic body
    /// joins nothing), and sums `mass_of` over each group.
    pub(crate) fn new(
        states: &[BodyState],
        links: impl IntoIterator<Item = (u32, u32)>,
        mass_of: impl Fn(&BodyState) -> f32,
    ) -> Self {
        let mut links = links.into_iter().peekable();
        if links.peek().is_none() {
            return Self::default();
        }
        let mut groups = UnionFind::new(states.len());
        for (a, b) in links {
            if a as usize >= states.len() || b as usize >= states.len() {
                continue;
            }
            groups.union(a, b);
        }
        let mut total = vec![0.0f32; states.len()];
        for (i, st) in states.iter().enumerate() {
            total[groups.find(i as u32) as usize] += mass_of(st);
        }
        let group = (0..states.len() as u32)
            .map(|i| total[groups.find(i) as usize])
            .collect();
        Self { group }
    }

    /// The mass of `body`'s group, or `None` where the step joins no bodies (its own mass).
    pub(crate) fn get(&self, body: u32) -> Option<f32> {
        self.group.get(body as usize).copied()
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec3A;

    use super::*;

    fn body(mass: f32) -> BodyState {
        BodyState {
            inv_mass: Vec3A::splat(1.0 / mass),
            ..BodyState::STATIC
        }
    }

    fn mass_of(st: &BodyState) -> f32 {
        1.0 / st.inv_mass.x
    }

    #[test]
    fn bodies_joined_in_a_chain_share_one_mass_and_the_others_keep_their_own() {
        // 1–2–3 jointed (as 1–2 and 3–2), 4 alone, 5–6 jointed.
        let states: Vec<_> = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]
            .into_iter()
            .map(body)
            .collect();
        let m = JointedMasses::new(&states, [(1, 2), (3, 2), (5, 6)], mass_of);
        let groups: Vec<f32> = (0..7).map(|i| m.get(i).unwrap()).collect();
        assert_eq!(groups, vec![1.0, 9.0, 9.0, 9.0, 5.0, 13.0, 13.0]);
    }

    #[test]
    fn without_joints_nothing_is_grouped() {
        let states = vec![body(1.0); 3];
        let m = JointedMasses::new(&states, std::iter::empty(), mass_of);
        assert_eq!(m.get(1), None);
    }
}
