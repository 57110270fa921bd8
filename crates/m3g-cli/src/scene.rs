//! What `m3g render` renders: a file's first World, or (for files that ship only Groups,
//! Meshes or Sprites, as games often do) its root nodes put in a World under a default
//! camera and lights; the bounds that camera frames; the cameras `--camera` can choose;
//! and how long the animations run (`--animate`).

use std::collections::HashSet;

use glam::{Quat, Vec3};
use m3g::{
    AnimationTrack, Camera, GroupExt, Light, LightMode, Mesh, MorphingMesh, Node, NodeExt,
    Object3D, Object3DExt, RepeatMode, SkinnedMesh, Sprite3D, TransformableExt, VertexBuffer,
    World,
};

/// The vertical field of view of the default camera, in degrees.
pub const DEFAULT_FOVY: f32 = 45.0;

/// The scene of one file.
pub struct Scene {
    pub world: World,
    /// `true` when the World was made here around the file's root nodes.
    pub synthesized: bool,
}

/// The file's first World; otherwise a new World holding every root node, animated to
/// `time` (so the framing sees the pose of the first frame), with a default camera framing
/// the nodes' bounds for a `width` × `height` image and, when the nodes bring no Light,
/// a default directional light and an ambient light. An error when no root is a node.
pub fn scene(roots: &[Object3D], time: i32, width: u32, height: u32) -> Result<Scene, String> {
    if let Some(world) = roots.iter().find_map(|r| r.downcast::<World>()) {
        return Ok(Scene {
            world,
            synthesized: false,
        });
    }
    let nodes: Vec<Node> = roots.iter().filter_map(|r| r.downcast::<Node>()).collect();
    if nodes.is_empty() {
        let classes: Vec<&str> = roots.iter().map(|r| r.class_name()).collect();
        return Err(format!(
            "nothing to render: no World and no node among the root objects (they are: {})",
            if classes.is_empty() {
                "none".to_string()
            } else {
                classes.join(", ")
            }
        ));
    }
    let world = World::new();
    let mut has_light = false;
    for n in &nodes {
        world.add_child(n).map_err(|e| {
            format!(
                "cannot put the root {} in a World: {e}",
                n.as_object3d().class_name()
            )
        })?;
        has_light |= contains_light(n);
    }
    world
        .animate(time)
        .map_err(|e| format!("animate({time}) failed: {e}"))?;
    let (center, radius) = match bounds(&world)? {
        Some([lo, hi]) => ((lo + hi) * 0.5, ((hi - lo) * 0.5).length()),
        None => (Vec3::ZERO, 1.0),
    };
    let radius = if radius.is_finite() && radius > 0.0 {
        radius
    } else {
        1.0
    };
    let camera = framing_camera(center, radius, width as f32 / height as f32)?;
    world
        .add_child(&camera)
        .map_err(|e| format!("cannot add the default camera: {e}"))?;
    world.set_active_camera(&camera);
    if !has_light {
        for light in default_lights()? {
            world
                .add_child(&light)
                .map_err(|e| format!("cannot add the default light: {e}"))?;
        }
    }
    Ok(Scene {
        world,
        synthesized: true,
    })
}

/// Whether `node` is or holds a Light.
fn contains_light(node: &Node) -> bool {
    let mut stack = vec![node.clone()];
    while let Some(n) = stack.pop() {
        if n.downcast::<Light>().is_some() {
            return true;
        }
        if let Some(g) = n.downcast::<m3g::Group>() {
            stack.extend((0..g.child_count()).filter_map(|i| g.child(i).ok()));
        }
    }
    false
}

/// A perspective camera (`DEFAULT_FOVY`) on the +Z side of the sphere (`center`, `radius`),
/// looking down -Z at it from the distance where the sphere just fits the narrower side
/// of the view, so the content fills most of the image.
pub fn framing_camera(center: Vec3, radius: f32, aspect: f32) -> Result<Camera, String> {
    let half_v = (DEFAULT_FOVY / 2.0).to_radians();
    let half_h = (half_v.tan() * aspect).atan();
    let distance = radius / half_v.min(half_h).sin();
    let far = distance + radius * 1.5;
    let near = ((distance - radius) * 0.9).max(far / 1000.0);
    let camera = Camera::new();
    camera
        .set_perspective(DEFAULT_FOVY, aspect, near, far)
        .map_err(|e| format!("cannot set up the default camera: {e}"))?;
    camera.set_translation(center.x, center.y, center.z + distance);
    Ok(camera)
}

/// A white directional light shining from the upper left of the viewer into the scene,
/// and a white ambient light (which the default Material's 20 % gray ambient color turns
/// into a soft fill).
pub fn default_lights() -> Result<[Light; 2], String> {
    let err = |e: m3g::Error| format!("cannot set up the default light: {e}");
    let sun = Light::new();
    sun.set_mode(LightMode::Directional);
    // A Light shines along its -Z axis; turn that toward the lower right, away from the viewer.
    let q = Quat::from_rotation_arc(Vec3::NEG_Z, Vec3::new(0.35, -0.45, -1.0).normalize());
    sun.set_orientation_quat(q.x, q.y, q.z, q.w).map_err(err)?;
    let ambient = Light::new();
    ambient.set_mode(LightMode::Ambient);
    Ok([sun, ambient])
}

/// The axis-aligned box, in `world`'s coordinates, around every position of the
/// rendering-enabled Meshes (skinned and morphed as they are now; scale and bias applied,
/// then the node transforms) and the origins of Sprite3Ds under `world`; cameras and lights
/// do not count. `None` when there is no geometry.
pub fn bounds(world: &World) -> Result<Option<[Vec3; 2]>, String> {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    let mut stack: Vec<Node> = (0..world.child_count())
        .filter_map(|i| world.child(i).ok())
        .collect();
    while let Some(n) = stack.pop() {
        if !n.is_rendering_enabled() {
            continue;
        }
        if let Some(g) = n.downcast::<m3g::Group>() {
            stack.extend((0..g.child_count()).filter_map(|i| g.child(i).ok()));
            continue;
        }
        if let Some(s) = n.downcast::<SkinnedMesh>() {
            // Nodes attached to the bones are drawn too.
            stack.push(s.skeleton().as_node());
        }
        let Some(to_world) = n
            .get_transform_to(world)
            .map_err(|e| format!("the transform of a {}: {e}", n.as_object3d().class_name()))?
        else {
            continue;
        };
        let vb: VertexBuffer = if let Some(s) = n.downcast::<SkinnedMesh>() {
            s.skinned_vertex_buffer()
                .map_err(|e| format!("skinning a SkinnedMesh: {e}"))?
        } else if let Some(m) = n.downcast::<MorphingMesh>() {
            m.morphed_vertex_buffer()
                .map_err(|e| format!("morphing a MorphingMesh: {e}"))?
        } else if let Some(m) = n.downcast::<Mesh>() {
            m.vertex_buffer()
        } else {
            if n.downcast::<Sprite3D>().is_some() {
                let mut origin = [0.0, 0.0, 0.0, 1.0];
                to_world.transform(&mut origin).map_err(|e| e.to_string())?;
                let p = Vec3::new(origin[0], origin[1], origin[2]);
                lo = lo.min(p);
                hi = hi.max(p);
            }
            continue;
        };
        let (Some(positions), [scale, bx, by, bz]) = vb.get_positions() else {
            continue;
        };
        let mut t = to_world;
        t.post_translate(bx, by, bz);
        t.post_scale(scale, scale, scale);
        let points = t
            .transform_vertex_array(&positions, true)
            .map_err(|e| format!("the positions of a {}: {e}", n.as_object3d().class_name()))?;
        for p in points.chunks_exact(4) {
            let p = Vec3::new(p[0], p[1], p[2]);
            if p.is_finite() {
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
    }
    Ok((lo.x <= hi.x).then_some([lo, hi]))
}

/// The Camera with `user_id` among the objects reachable from `world`; it must be in the
/// World's scene graph. The error lists the cameras there are.
pub fn find_camera(world: &World, user_id: i32) -> Result<Camera, String> {
    // Handles hash and compare by identity, so their interior mutability does not matter.
    #[allow(clippy::mutable_key_type)]
    let mut seen = HashSet::new();
    let mut stack = vec![Object3D::from(world.clone())];
    let mut cameras = Vec::new();
    let mut other = None;
    while let Some(o) = stack.pop() {
        if !seen.insert(o.clone()) {
            continue;
        }
        if let Some(c) = o.downcast::<Camera>() {
            if c.user_id() == user_id {
                let mut root: Object3D = c.clone().into();
                let mut n = c.parent();
                while let Some(p) = n {
                    n = p.parent();
                    root = p.into();
                }
                if root != Object3D::from(world.clone()) {
                    return Err(format!(
                        "the Camera with user ID {user_id} is not in the World"
                    ));
                }
                return Ok(c);
            }
            cameras.push(c.user_id());
        } else if o.user_id() == user_id && other.is_none() {
            other = Some(o.class_name());
        }
        let mut refs = o.get_references();
        refs.reverse();
        stack.extend(refs);
    }
    cameras.sort_unstable();
    cameras.dedup();
    let have = if cameras.is_empty() {
        "the World has no cameras".to_string()
    } else {
        let ids: Vec<String> = cameras.iter().map(|c| c.to_string()).collect();
        format!("camera user IDs: {}", ids.join(", "))
    };
    Err(match other {
        Some(class) => format!("user ID {user_id} is a {class}, not a Camera ({have})"),
        None => format!("no Camera with user ID {user_id} ({have})"),
    })
}

/// Every AnimationTrack reachable from `roots` (each once, in depth-first order).
pub fn tracks(roots: &[Object3D]) -> Vec<AnimationTrack> {
    #[allow(clippy::mutable_key_type)]
    let mut seen = HashSet::new();
    let mut stack: Vec<Object3D> = roots.iter().rev().cloned().collect();
    let mut out = Vec::new();
    while let Some(o) = stack.pop() {
        if !seen.insert(o.clone()) {
            continue;
        }
        if let Some(t) = o.downcast::<AnimationTrack>() {
            out.push(t);
        }
        let mut refs = o.get_references();
        refs.reverse();
        stack.extend(refs);
    }
    out
}

/// When one track's animation is over, seen from world time `start`: `(end, inclusive)`,
/// where `inclusive` says whether the picture at `end` itself is still part of it; `None`
/// when the track changes nothing after `start` (no controller, speed 0, or a one-shot
/// sequence finished before `start`).
///
/// A controller maps world time t to sequence time `ref_seq + speed × (t - ref_world)`
/// and is active in `[interval start, interval end)` (always when the two are equal).
/// A looping sequence (`LOOP`) is over after one period, `duration / |speed|` world
/// milliseconds from when it becomes active (or from `start`); its end looks like its
/// start, so the end is exclusive. A one-shot sequence (`CONSTANT`) is over when its
/// sequence time leaves `[0, duration]` (inclusive: the last pose is shown). An interval
/// that ends first cuts either short (exclusive: the property keeps its last value).
pub fn track_end(track: &AnimationTrack, start: i32) -> Option<(i64, bool)> {
    let c = track.controller()?;
    let seq = track.keyframe_sequence();
    let duration = seq.duration() as f64;
    let speed = c.speed() as f64;
    let (s, e) = (
        c.active_interval_start() as i64,
        c.active_interval_end() as i64,
    );
    let interval = s != e;
    let start = start as i64;
    if interval && e <= start {
        return None;
    }
    if speed == 0.0 || duration <= 0.0 || !speed.is_finite() {
        // Static: only switching on at the interval's start changes the picture.
        return (interval && s > start).then_some((s, true));
    }
    let from = if interval { s.max(start) } else { start };
    let over = |t: f64, inclusive: bool| -> (i64, bool) {
        let t = t.ceil().clamp(i32::MIN as f64, i32::MAX as f64) as i64;
        if interval && e < t + inclusive as i64 {
            (e, false)
        } else {
            (t, inclusive)
        }
    };
    if seq.repeat_mode() == RepeatMode::Loop {
        return Some(over(from as f64 + duration / speed.abs(), false));
    }
    let ref_world = c.ref_world_time() as f64;
    let ref_seq = c.position(c.ref_world_time()) as f64;
    let at = |seq_time: f64| ref_world + (seq_time - ref_seq) / speed;
    let (end, inclusive) = over(at(0.0).max(at(duration)), true);
    (end > start).then_some((end, inclusive))
}

/// The span `m3g render --animate` covers from world time `start`: the latest end of
/// any track ([`track_end`]), inclusive when a track ending then shows its end. `None`
/// without any animation after `start`.
pub fn animation_end(tracks: &[AnimationTrack], start: i32) -> Option<(i64, bool)> {
    let mut best: Option<(i64, bool)> = None;
    for t in tracks {
        if let Some((end, inclusive)) = track_end(t, start) {
            best = match best {
                Some((b, i)) if b > end || (b == end && i) => Some((b, i)),
                _ => Some((end, inclusive)),
            };
        }
    }
    best
}

/// The number of frames `step` ms apart from `start` that show the animation up to `end`:
/// up to and including `end` when `inclusive`, else up to the last frame before it.
pub fn frame_count(start: i32, end: i64, inclusive: bool, step: i32) -> u64 {
    let span = (end - start as i64).max(0) as u64;
    let step = step.max(1) as u64;
    if inclusive {
        span / step + 1
    } else {
        span.div_ceil(step).max(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use m3g::{AnimationController, AnimationProperty, Interpolation, KeyframeSequence};

    fn track(duration: i32, mode: RepeatMode) -> (AnimationTrack, AnimationController) {
        let seq = KeyframeSequence::new(2, 3, Interpolation::Linear).unwrap();
        seq.set_keyframe(0, 0, &[0.0; 3]).unwrap();
        seq.set_keyframe(1, duration / 2, &[1.0; 3]).unwrap();
        seq.set_duration(duration).unwrap();
        seq.set_repeat_mode(mode);
        let t = AnimationTrack::new(&seq, AnimationProperty::Translation).unwrap();
        let c = AnimationController::new();
        t.set_controller(Some(&c));
        (t, c)
    }

    #[test]
    fn loops_last_one_period_and_one_shots_until_their_end() {
        let (a, _) = track(1200, RepeatMode::Loop);
        assert_eq!(track_end(&a, 0), Some((1200, false)));
        let (b, bc) = track(2000, RepeatMode::Constant);
        assert_eq!(track_end(&b, 0), Some((2000, true)));
        // Twice as fast: half the world time.
        bc.set_speed(2.0, 0);
        assert_eq!(track_end(&b, 0), Some((1000, true)));
        // An interval cuts it short.
        bc.set_active_interval(100, 600).unwrap();
        assert_eq!(track_end(&b, 0), Some((600, false)));
        assert_eq!(
            animation_end(&[a.clone(), b.clone()], 0),
            Some((1200, false))
        );
        assert_eq!(frame_count(0, 1200, false, 100), 12);
        assert_eq!(frame_count(0, 2000, true, 100), 21);
        // Without a controller a track does nothing.
        let (c, _) = track(500, RepeatMode::Constant);
        c.set_controller(None);
        assert_eq!(track_end(&c, 0), None);
        assert_eq!(animation_end(&[c], 0), None);
    }
}
