//! Everything a plugin does through `Ctx`, through the ABI adapter, checked in the world.

use std::sync::{Arc, Mutex};

use onyx_plugin_api::glam::{Vec2, Vec3};
use onyx_plugin_api::{
    Component, Ctx, CtxError, Entity, Event, Flow, InputEvent, Key, Message, MouseButton, Name,
    Plugin, Transform,
};
use onyx_runtime::HeadlessHost;
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Health {
    hp: u32,
    tags: Vec<String>,
}
impl Component for Health {
    const NAME: &'static str = "test.health";
}

/// Same name, another shape: decoding must fail, not misread.
#[derive(Debug, Serialize, Deserialize)]
struct NotHealth {
    colour: String,
}
impl Component for NotHealth {
    const NAME: &'static str = "test.health";
}

type Script = Box<dyn FnMut(&mut Ctx) + Send>;

/// Runs a closure in `on_update` (once per frame).
struct Scripted(Script);

impl Plugin for Scripted {
    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> Flow {
        (self.0)(ctx);
        Flow::Continue
    }
}

fn run_once(script: impl FnMut(&mut Ctx) + Send + 'static) -> HeadlessHost {
    let mut host = HeadlessHost::new();
    host.add_plugin("scripted", Scripted(Box::new(script)))
        .unwrap();
    host.step(1);
    host
}

#[test]
fn builtin_components_can_be_read_written_and_removed() {
    let out = Arc::new(Mutex::new(Vec::new()));
    let o = out.clone();
    let host = run_once(move |ctx| {
        let e = ctx
            .spawn((Name::new("crate"), Transform::from_xyz(0.0, 2.0, 0.0)))
            .unwrap();
        let mut t: Transform = ctx.get(e).unwrap();
        t.translation.y += 1.0;
        ctx.set(e, t).unwrap();
        ctx.set(e, Name::new("renamed")).unwrap();
        let name: Name = ctx.get(e).unwrap();
        o.lock().unwrap().push(format!("{name}"));
        let bare = ctx.spawn(()).unwrap();
        let missing = ctx.get::<Transform>(bare).unwrap_err();
        o.lock().unwrap().push(format!("{missing}"));
        ctx.remove::<Name>(bare).expect_err("nothing to remove");
        ctx.set(bare, Name::new("to go")).unwrap();
        ctx.remove::<Name>(bare).unwrap();
        assert!(matches!(
            ctx.get::<Name>(bare),
            Err(CtxError::MissingComponent { .. })
        ));
    });
    let (_, t) = host.find::<Transform>("renamed").unwrap();
    assert_eq!(t.translation, Vec3::new(0.0, 3.0, 0.0));
    let out = out.lock().unwrap();
    assert_eq!(out[0], "renamed");
    assert!(
        out[1].contains("has no `Transform` component"),
        "{}",
        out[1]
    );
}

#[test]
fn stale_handles_are_refused_after_despawn() {
    let answer = Arc::new(Mutex::new(None));
    let a = answer.clone();
    run_once(move |ctx| {
        let e = ctx.spawn(Name::new("gone")).unwrap();
        assert!(ctx.contains(e));
        ctx.despawn(e).unwrap();
        assert!(!ctx.contains(e));
        // The slot is reused by the next spawn; the old handle must not reach it.
        let reused = ctx.spawn(Name::new("new")).unwrap();
        *a.lock().unwrap() = Some((ctx.get::<Name>(e), ctx.despawn(e), reused != e));
    });
    let (get, despawn, distinct) = answer.lock().unwrap().take().unwrap();
    assert!(matches!(get, Err(CtxError::NoSuchEntity { .. })), "{get:?}");
    assert!(
        matches!(despawn, Err(CtxError::NoSuchEntity { .. })),
        "{despawn:?}"
    );
    assert!(distinct);
}

#[test]
fn plugin_components_round_trip_and_query_in_bulk() {
    let answer = Arc::new(Mutex::new(None));
    let a = answer.clone();
    let host = run_once(move |ctx| {
        let hp = |n| Health {
            hp: n,
            tags: vec!["x".into()],
        };
        let e1 = ctx.spawn((Name::new("one"), hp(10))).unwrap();
        let e2 = ctx.spawn((Name::new("two"), hp(20))).unwrap();
        ctx.spawn(Name::new("three")).unwrap();
        ctx.set(e1, hp(11)).unwrap();
        let read: Health = ctx.get(e1).unwrap();
        let queried = ctx.query::<Health>().unwrap();
        let wrong = ctx.get::<NotHealth>(e2).unwrap_err();
        ctx.set_raw(e2, "test.raw", &[1, 2, 3]).unwrap();
        let raw = ctx.get_raw(e2, "test.raw").unwrap();
        let raw_as_serde = ctx.get::<NotHealth>(e2).map(|_| ());
        ctx.remove::<Health>(e2).unwrap();
        *a.lock().unwrap() = Some((
            read,
            queried,
            wrong,
            raw,
            raw_as_serde,
            ctx.query::<Health>().unwrap().len(),
        ));
    });
    let (read, queried, wrong, raw, _raw_as_serde, left) = answer.lock().unwrap().take().unwrap();
    assert_eq!(read.hp, 11);
    assert_eq!(
        queried.iter().map(|(_, h)| h.hp).collect::<Vec<_>>(),
        [11, 20]
    );
    assert!(matches!(wrong, CtxError::Decode { .. }), "{wrong:?}");
    assert_eq!(raw, [1, 2, 3]);
    assert_eq!(left, 1);
    let dump = host.dump_state();
    let one = dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == "one")
        .unwrap();
    assert_eq!(one["components"]["test.health"]["hp"], 11);
    let two = dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == "two")
        .unwrap();
    assert_eq!(two["components"]["test.raw"]["base64"], "AQID");
}

#[test]
fn ten_thousand_transforms_are_read_and_written_in_one_call_each() {
    let mut host = HeadlessHost::new();
    let mut spawned = false;
    host.add_plugin(
        "bulk",
        Scripted(Box::new(move |ctx: &mut Ctx| {
            if !spawned {
                for i in 0..10_000 {
                    ctx.spawn(Transform::from_xyz(i as f32, 0.0, 0.0)).unwrap();
                }
                spawned = true;
            }
            assert_eq!(ctx.transforms().len(), 10_000);
            ctx.update_transforms(|items| {
                for item in items {
                    item.transform.translation.y += 1.0;
                }
            })
            .unwrap();
            let mut copy = ctx.transforms().to_vec();
            for item in &mut copy {
                item.transform.translation.z -= 0.5;
            }
            ctx.set_transforms(&copy).unwrap();
        })),
    )
    .unwrap();
    host.step(3);
    let mut n = 0;
    for t in host.world().query::<&Transform>().iter() {
        assert_eq!((t.translation.y, t.translation.z), (3.0, -1.5));
        n += 1;
    }
    assert_eq!(n, 10_000);
}

#[derive(Debug, PartialEq, Serialize, Deserialize)]
struct Ping {
    n: u32,
}
impl Message for Ping {
    const NAME: &'static str = "test.ping";
}

/// Sends a ping each frame; records what it receives.
struct Pinger {
    sent: u32,
    got: Arc<Mutex<Vec<(String, u32)>>>,
}

impl Plugin for Pinger {
    fn on_event(&mut self, _: &mut Ctx, event: &Event) {
        if let Event::Custom(custom) = event {
            if custom.is::<Ping>() {
                let ping: Ping = custom.decode().unwrap();
                self.got
                    .lock()
                    .unwrap()
                    .push((custom.sender.clone(), ping.n));
            }
        }
    }
    fn on_update(&mut self, ctx: &mut Ctx, _: f32) -> Flow {
        if self.sent < 2 {
            self.sent += 1;
            ctx.send(&Ping { n: self.sent }).unwrap();
        }
        Flow::Continue
    }
}

#[test]
fn custom_events_reach_every_plugin_next_frame_with_their_sender() {
    let got_a = Arc::new(Mutex::new(Vec::new()));
    let got_b = Arc::new(Mutex::new(Vec::new()));
    let mut host = HeadlessHost::new();
    host.add_plugin(
        "pa",
        Pinger {
            sent: 0,
            got: got_a.clone(),
        },
    )
    .unwrap();
    host.add_plugin(
        "pb",
        Pinger {
            sent: 2,
            got: got_b.clone(),
        },
    )
    .unwrap();
    host.step(1);
    assert!(
        got_b.lock().unwrap().is_empty(),
        "events are delivered next frame"
    );
    host.step(2);
    let expected = vec![("pa".to_owned(), 1), ("pa".to_owned(), 2)];
    assert_eq!(
        *got_a.lock().unwrap(),
        expected,
        "the sender hears its own events too"
    );
    assert_eq!(*got_b.lock().unwrap(), expected);
}

#[test]
fn injected_input_is_visible_as_state_for_exactly_one_frame_of_edges() {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let s = seen.clone();
    let mut host = HeadlessHost::new();
    host.add_plugin(
        "input",
        Scripted(Box::new(move |ctx: &mut Ctx| {
            let i = ctx.input();
            s.lock().unwrap().push((
                i.key_down(Key::W),
                i.key_pressed(Key::W),
                i.mouse_down(MouseButton::Left),
                i.cursor(),
                i.scroll(),
            ));
        })),
    )
    .unwrap();
    host.inject(InputEvent::Key {
        key: Key::W,
        pressed: true,
        repeat: false,
    });
    host.inject(InputEvent::MouseButton {
        button: MouseButton::Left,
        pressed: true,
    });
    host.inject(InputEvent::CursorMoved { x: 10.0, y: 20.0 });
    host.inject(InputEvent::Scroll { dx: 0.0, dy: 1.0 });
    host.step(2);
    host.inject(InputEvent::Key {
        key: Key::W,
        pressed: false,
        repeat: false,
    });
    host.step(1);
    let seen = seen.lock().unwrap();
    assert_eq!(
        seen[0],
        (true, true, true, Vec2::new(10.0, 20.0), Vec2::new(0.0, 1.0))
    );
    assert_eq!(
        seen[1],
        (true, false, true, Vec2::new(10.0, 20.0), Vec2::ZERO)
    );
    assert!(!seen[2].0, "W released");
}

#[test]
fn focus_loss_releases_held_keys() {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let s = seen.clone();
    let mut host = HeadlessHost::new();
    host.add_plugin(
        "input",
        Scripted(Box::new(move |ctx: &mut Ctx| {
            s.lock().unwrap().push(ctx.input().key_down(Key::A))
        })),
    )
    .unwrap();
    host.inject(InputEvent::Key {
        key: Key::A,
        pressed: true,
        repeat: false,
    });
    host.step(1);
    host.inject(onyx_plugin_api::WindowEvent::Focused(false));
    host.step(1);
    assert_eq!(*seen.lock().unwrap(), [true, false]);
}

#[test]
fn time_reports_the_clock_and_bad_time_scales_are_refused() {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let s = seen.clone();
    let mut host = HeadlessHost::new();
    host.add_plugin(
        "clock",
        Scripted(Box::new(move |ctx: &mut Ctx| {
            let t = ctx.time();
            let refused =
                ctx.set_time_scale(f32::NAN).is_err() && ctx.set_time_scale(-1.0).is_err();
            s.lock()
                .unwrap()
                .push((t.frame, t.ticks, t.fixed_delta, t.delta, refused));
            ctx.info("clock checked");
        })),
    )
    .unwrap();
    host.step(2);
    let seen = seen.lock().unwrap();
    let dt = 1.0f32 / 60.0;
    assert_eq!(seen[0].0, 0);
    assert_eq!(seen[1].0, 1);
    assert_eq!(seen[1].1, 2, "ticks counted before on_update");
    assert!((seen[0].2 - dt).abs() < 1e-7 && (seen[0].3 - dt).abs() < 1e-7);
    assert!(seen[0].4);
}

#[test]
fn entities_lists_every_entity() {
    let count = Arc::new(Mutex::new(0));
    let c = count.clone();
    run_once(move |ctx| {
        let ids: Vec<Entity> = (0..5).map(|_| ctx.spawn(()).unwrap()).collect();
        let listed = ctx.entities().to_vec();
        assert!(ids.iter().all(|e| listed.contains(e)));
        *c.lock().unwrap() = listed.len();
    });
    assert_eq!(*count.lock().unwrap(), 5);
}
