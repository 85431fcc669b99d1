//! Debug drawing: `PhysicsWorld::debug_lines` emits collider outlines, joint anchors,
//! contact points and normals as [`DebugLine`]s.

use glam::{Quat, Vec3};

use crate::body_type::BodyType;
use crate::debug_line::DebugLine;
use crate::physics_world::PhysicsWorld;
use crate::pose::Pose;
use crate::shape::Shape;

/// Segments per circle in outlines.
pub const DEBUG_CIRCLE_SEGMENTS: usize = 16;
/// Half size of the square drawn for half spaces, metres.
pub const DEBUG_PLANE_HALF_SIZE: f32 = 10.0;

/// Colours of the debug draw.
pub mod colors {
    /// Awake dynamic body.
    pub const DYNAMIC: [f32; 4] = [0.2, 0.9, 0.3, 1.0];
    /// Sleeping body.
    pub const SLEEPING: [f32; 4] = [0.5, 0.5, 0.5, 1.0];
    /// Static body.
    pub const STATIC: [f32; 4] = [0.3, 0.5, 1.0, 1.0];
    /// Kinematic body.
    pub const KINEMATIC: [f32; 4] = [1.0, 0.9, 0.2, 1.0];
    /// Quarantined body.
    pub const QUARANTINED: [f32; 4] = [1.0, 0.0, 1.0, 1.0];
    /// Contact point cross.
    pub const CONTACT: [f32; 4] = [1.0, 0.2, 0.2, 1.0];
    /// Contact normal.
    pub const NORMAL: [f32; 4] = [1.0, 1.0, 1.0, 1.0];
    /// A joint's anchors (a cross on each side), the segment between them and its axis.
    pub const JOINT: [f32; 4] = [1.0, 0.5, 0.0, 1.0];
    /// A broken joint's anchors.
    pub const BROKEN_JOINT: [f32; 4] = [0.6, 0.2, 0.2, 1.0];
}

/// Half size of the cross drawn at a joint anchor, and length of its axis, metres.
pub const DEBUG_JOINT_ANCHOR_SIZE: f32 = 0.06;

impl PhysicsWorld {
    /// Collider outlines, joint anchors, contact points (small crosses) and normals (0.2 m)
    /// as lines.
    #[must_use]
    pub fn debug_lines(&self) -> Vec<DebugLine> {
        let mut out = Vec::new();
        self.debug_lines_into(&mut out, true, true);
        out
    }

    /// Appends debug lines; choose colliders (with the joints' anchors) and/or contacts.
    pub fn debug_lines_into(&self, out: &mut Vec<DebugLine>, colliders: bool, contacts: bool) {
        if colliders {
            self.joint_lines(out);
        }
        if colliders {
            for (_, c) in self.colliders.iter() {
                let Some(b) = self.bodies.get(c.parent) else {
                    continue;
                };
                let color = if b.quarantined {
                    colors::QUARANTINED
                } else if b.sleeping {
                    colors::SLEEPING
                } else {
                    match b.body_type {
                        BodyType::Dynamic => colors::DYNAMIC,
                        BodyType::Kinematic => colors::KINEMATIC,
                        BodyType::Static => colors::STATIC,
                    }
                };
                outline(&c.shape, &b.pose.mul_pose(&c.local_pose), color, out);
            }
        }
        if contacts {
            for p in self.narrowphase.pairs() {
                let Some(ba) = self.bodies.get(p.body_a) else {
                    continue;
                };
                for m in &p.manifolds {
                    for cp in &m.points {
                        let x = ba.pose.transform_point(cp.local_a);
                        let s = 0.03;
                        for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
                            out.push(DebugLine {
                                a: x - axis * s,
                                b: x + axis * s,
                                color: colors::CONTACT,
                            });
                        }
                        out.push(DebugLine {
                            a: x,
                            b: x + m.normal * 0.2,
                            color: colors::NORMAL,
                        });
                    }
                }
            }
        }
    }
}

impl PhysicsWorld {
    /// Each joint: a cross at its anchor on either side, the segment between them (its
    /// error: a held joint's crosses meet) and its axis (the frame's X: a hinge's or a
    /// slider's axis) from the second body's anchor.
    fn joint_lines(&self, out: &mut Vec<DebugLine>) {
        let s = DEBUG_JOINT_ANCHOR_SIZE;
        for (_, joint) in self.joints.iter() {
            let frame = |body: Option<crate::BodyHandle>, local: &Pose| match body {
                Some(b) => self.bodies.get(b).map(|b| b.pose.mul_pose(local)),
                None => Some(*local),
            };
            let (Some(a), Some(b)) = (
                frame(joint.body_a, &joint.desc.frame_a),
                frame(Some(joint.body_b), &joint.desc.frame_b),
            ) else {
                continue;
            };
            let color = if joint.broken {
                colors::BROKEN_JOINT
            } else {
                colors::JOINT
            };
            for p in [a.translation, b.translation] {
                for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
                    out.push(DebugLine {
                        a: p - axis * s,
                        b: p + axis * s,
                        color,
                    });
                }
            }
            out.push(DebugLine {
                a: a.translation,
                b: b.translation,
                color,
            });
            out.push(DebugLine {
                a: b.translation,
                b: b.translation + b.rotation * Vec3::X * (4.0 * s),
                color,
            });
        }
    }
}

fn circle(center: Vec3, u: Vec3, v: Vec3, r: f32, color: [f32; 4], out: &mut Vec<DebugLine>) {
    let n = DEBUG_CIRCLE_SEGMENTS;
    let pt = |k: usize| {
        let a = k as f32 / n as f32 * std::f32::consts::TAU;
        center + (u * a.cos() + v * a.sin()) * r
    };
    for k in 0..n {
        out.push(DebugLine {
            a: pt(k),
            b: pt(k + 1),
            color,
        });
    }
}

fn outline(shape: &Shape, pose: &Pose, color: [f32; 4], out: &mut Vec<DebugLine>) {
    let (x, y, z) = (
        pose.rotation * Vec3::X,
        pose.rotation * Vec3::Y,
        pose.rotation * Vec3::Z,
    );
    let c = pose.translation;
    match shape {
        Shape::Sphere(s) => {
            circle(c, x, y, s.radius, color, out);
            circle(c, y, z, s.radius, color, out);
            circle(c, z, x, s.radius, color, out);
        }
        Shape::Cuboid(b) => {
            let v = b.vertices().map(|p| pose.transform_point(p));
            for (i, j) in crate::shape::Cuboid::EDGES {
                out.push(DebugLine {
                    a: v[i],
                    b: v[j],
                    color,
                });
            }
        }
        Shape::Capsule(cap) => {
            let (a, b) = (c - y * cap.half_height, c + y * cap.half_height);
            circle(a, x, z, cap.radius, color, out);
            circle(b, x, z, cap.radius, color, out);
            for d in [x, -x, z, -z] {
                out.push(DebugLine {
                    a: a + d * cap.radius,
                    b: b + d * cap.radius,
                    color,
                });
            }
            circle(a, x, y, cap.radius, color, out);
            circle(b, x, y, cap.radius, color, out);
        }
        Shape::HalfSpace(h) => {
            let n = pose.rotation * h.normal;
            let q = Quat::from_rotation_arc(Vec3::Y, n);
            let (u, v) = (
                q * Vec3::X * DEBUG_PLANE_HALF_SIZE,
                q * Vec3::Z * DEBUG_PLANE_HALF_SIZE,
            );
            let corners = [c + u + v, c - u + v, c - u - v, c + u - v];
            for k in 0..4 {
                out.push(DebugLine {
                    a: corners[k],
                    b: corners[(k + 1) % 4],
                    color,
                });
            }
            out.push(DebugLine {
                a: c,
                b: c + n,
                color,
            });
        }
        Shape::ConvexHull(hull) => {
            let v = hull.vertices();
            for &(i, j) in hull.edges() {
                out.push(DebugLine {
                    a: pose.transform_point(v[i as usize]),
                    b: pose.transform_point(v[j as usize]),
                    color,
                });
            }
        }
        Shape::TriMesh(m) => {
            for t in 0..m.triangles().len() {
                let [a, b, cc] = m.triangle(t).map(|p| pose.transform_point(p));
                out.push(DebugLine { a, b, color });
                out.push(DebugLine { a: b, b: cc, color });
                out.push(DebugLine { a: cc, b: a, color });
            }
        }
    }
}
