//! `AnimationController`, `AnimationTrack` and `Object3D.animate`: sampling the tracks
//! attached to every reachable object, blending them per property (Σ wᵢ·Pᵢ, not
//! normalized by Σ wᵢ; orientation normalized after the sum) and writing the clamped results.

use std::rc::Rc;

use glam::{Quat, Vec3};

use super::error::{iae, Result};
use super::keyframe::KeyframeSequence;
use super::mesh::MAX_SPRITE_CROP_DIMENSION;
use super::modes::{AnimationProperty as P, Projection};
use super::object::{class_data, for_each_reachable, handle, Inner, Kind, ObjRef};

#[derive(Clone, Debug)]
pub(crate) struct ControllerData {
    pub start: i32,
    pub end: i32,
    pub weight: f32,
    pub speed: f32,
    pub ref_world: i32,
    pub ref_seq: f32,
}

handle!(
    /// `AnimationController`: the active interval, weight and world-to-sequence time mapping
    /// `t_s = t_sref + speed·(t_w − t_wref)` shared by the tracks that use it.
    AnimationController,
    |i| matches!(i.kind, Kind::AnimationController(_))
);
class_data!(AnimationController, AnimationController, ControllerData);

impl Default for AnimationController {
    fn default() -> Self {
        AnimationController::new()
    }
}

impl AnimationController {
    /// `AnimationController()`: always active ([0, 0)), weight 1, speed 1, reference point
    /// (0, 0).
    pub fn new() -> AnimationController {
        AnimationController(Inner::new(
            Kind::AnimationController(ControllerData {
                start: 0,
                end: 0,
                weight: 1.0,
                speed: 1.0,
                ref_world: 0,
                ref_seq: 0.0,
            }),
            false,
            false,
        ))
    }
    /// `setActiveInterval(start, end)`: active for start ≤ t < end, always when start ==
    /// end. IllegalArgument if start > end.
    pub fn set_active_interval(&self, start: i32, end: i32) -> Result<()> {
        if start > end {
            return iae("active interval start after its end");
        }
        let mut d = self.dm();
        d.start = start;
        d.end = end;
        Ok(())
    }
    /// `getActiveIntervalStart()`.
    pub fn active_interval_start(&self) -> i32 {
        self.d().start
    }
    /// `getActiveIntervalEnd()`.
    pub fn active_interval_end(&self) -> i32 {
        self.d().end
    }
    /// `setSpeed(speed, worldTime)`: keeps the sequence time at `world_time` unchanged.
    pub fn set_speed(&self, speed: f32, world_time: i32) {
        let pos = self.position(world_time);
        let mut d = self.dm();
        d.ref_seq = pos;
        d.ref_world = world_time;
        d.speed = speed;
    }
    /// `getSpeed()`.
    pub fn speed(&self) -> f32 {
        self.d().speed
    }
    /// `setPosition(sequenceTime, worldTime)`: the reference point.
    pub fn set_position(&self, sequence_time: f32, world_time: i32) {
        let mut d = self.dm();
        d.ref_seq = sequence_time;
        d.ref_world = world_time;
    }
    /// `getPosition(worldTime)`: `t_sref + speed·(worldTime − t_wref)`.
    pub fn position(&self, world_time: i32) -> f32 {
        self.d().position(world_time) as f32
    }
    /// `getRefWorldTime()`.
    pub fn ref_world_time(&self) -> i32 {
        self.d().ref_world
    }
    /// `setWeight(w)`: IllegalArgument if w < 0; 0 makes the controller inactive.
    pub fn set_weight(&self, weight: f32) -> Result<()> {
        if weight < 0.0 || weight.is_nan() {
            return iae("negative weight");
        }
        self.dm().weight = weight;
        Ok(())
    }
    /// `getWeight()`.
    pub fn weight(&self) -> f32 {
        self.d().weight
    }
}

impl ControllerData {
    fn position(&self, world_time: i32) -> f64 {
        self.ref_seq as f64 + self.speed as f64 * (world_time as f64 - self.ref_world as f64)
    }
    fn in_interval(&self, t: i32) -> bool {
        self.start == self.end || (self.start <= t && t < self.end)
    }
}

#[derive(Clone, Debug)]
pub(crate) struct TrackData {
    pub sequence: KeyframeSequence,
    pub property: P,
    pub controller: Option<AnimationController>,
}

handle!(
    /// `AnimationTrack`: a KeyframeSequence, an AnimationController and the property they
    /// animate in every object the track is attached to.
    AnimationTrack,
    |i| matches!(i.kind, Kind::AnimationTrack(_))
);
class_data!(AnimationTrack, AnimationTrack, TrackData);

impl AnimationTrack {
    /// `AnimationTrack(sequence, property)`: no controller. IllegalArgument for a sequence
    /// whose component count does not fit the property.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// // Fade a mesh's alpha factor out over one second.
    /// let fade = KeyframeSequence::new(2, 1, Interpolation::Linear)?;
    /// fade.set_keyframe(0, 0, &[1.0])?;
    /// fade.set_keyframe(1, 1000, &[0.0])?;
    /// fade.set_duration(1000)?;
    /// let track = AnimationTrack::new(&fade, AnimationProperty::Alpha)?;
    /// track.set_controller(Some(&AnimationController::new()));
    ///
    /// let group = Group::new();
    /// group.add_animation_track(&track)?;
    /// assert_eq!(group.animation_track(0)?, track);
    /// group.animate(250)?;
    /// assert_eq!(group.alpha_factor(), 0.75);
    /// # Ok(())
    /// # }
    /// ```
    pub fn new(sequence: &KeyframeSequence, property: P) -> Result<AnimationTrack> {
        let c = sequence.component_count();
        let ok = match property {
            P::AmbientColor
            | P::Color
            | P::DiffuseColor
            | P::EmissiveColor
            | P::SpecularColor
            | P::Translation => c == 3,
            P::Crop => c == 2 || c == 4,
            P::Scale => c == 1 || c == 3,
            P::Orientation => c == 4,
            P::MorphWeights => true,
            _ => c == 1,
        };
        if !ok {
            return iae("the sequence's component count does not fit the property");
        }
        Ok(AnimationTrack(Inner::new(
            Kind::AnimationTrack(TrackData {
                sequence: sequence.clone(),
                property,
                controller: None,
            }),
            false,
            false,
        )))
    }
    /// `setController(controller)`: `None` makes the track inactive.
    pub fn set_controller(&self, controller: Option<&AnimationController>) {
        self.dm().controller = controller.cloned();
    }
    /// `getController()`.
    pub fn controller(&self) -> Option<AnimationController> {
        self.d().controller.clone()
    }
    /// `getKeyframeSequence()`.
    pub fn keyframe_sequence(&self) -> KeyframeSequence {
        self.d().sequence.clone()
    }
    /// `getTargetProperty()`.
    pub fn target_property(&self) -> P {
        self.d().property
    }
}

/// Whether `property` can be animated in an object like `i` (AnimationTrack's table).
pub(crate) fn property_applies(i: &Inner, property: P) -> bool {
    let transformable = i.tf.is_some();
    let node = i.node.is_some();
    if transformable && matches!(property, P::Orientation | P::Scale | P::Translation) {
        return true;
    }
    if node && matches!(property, P::Alpha | P::Pickability | P::Visibility) {
        return true;
    }
    match &i.kind {
        Kind::Camera(_) => matches!(property, P::FarDistance | P::NearDistance | P::FieldOfView),
        Kind::Light(_) => matches!(
            property,
            P::Color | P::Intensity | P::SpotAngle | P::SpotExponent
        ),
        Kind::Material(_) => matches!(
            property,
            P::Alpha
                | P::AmbientColor
                | P::DiffuseColor
                | P::EmissiveColor
                | P::SpecularColor
                | P::Shininess
        ),
        Kind::Fog(_) => matches!(
            property,
            P::Color | P::Density | P::FarDistance | P::NearDistance
        ),
        Kind::Background(_) => matches!(property, P::Alpha | P::Color | P::Crop),
        Kind::Sprite(_) => property == P::Crop,
        Kind::Texture2D(_) => property == P::Color,
        Kind::VertexBuffer(_) => matches!(property, P::Alpha | P::Color),
        Kind::Mesh(m) => property == P::MorphWeights && m.ext.is_morphing(),
        _ => false,
    }
}

/// `Object3D.addAnimationTrack(track)`.
pub(crate) fn add_track(obj: &ObjRef, track: &AnimationTrack) -> Result<()> {
    let (property, comps) = {
        let d = track.d();
        (d.property, d.sequence.component_count())
    };
    let i = obj.borrow();
    if !property_applies(&i, property) {
        return iae("the property does not apply to this object");
    }
    for t in &i.tracks {
        if Rc::ptr_eq(&t.0, &track.0) {
            return iae("the track is already attached");
        }
        let other = AnimationTrack(t.0.clone());
        let d = other.d();
        if d.property == property && d.sequence.component_count() != comps {
            return iae("another track animates the property with a different component count");
        }
    }
    drop(i);
    obj.borrow_mut()
        .tracks
        .push(super::object::Object3D(track.0.clone()));
    Ok(())
}

/// `Object3D.removeAnimationTrack(track)`: a track not attached is ignored.
pub(crate) fn remove_track(obj: &ObjRef, track: Option<&AnimationTrack>) {
    if let Some(track) = track {
        obj.borrow_mut()
            .tracks
            .retain(|t| !Rc::ptr_eq(&t.0, &track.0));
    }
}

/// Saturating conversion of a world-time span to the validity interval.
fn span_to_world(span: f64) -> i32 {
    if span.is_nan() || span <= 0.0 {
        0
    } else if span >= i32::MAX as f64 {
        i32::MAX
    } else {
        span.floor() as i32
    }
}

/// One property's blended value: per-component Σ wᵢ·vᵢ.
struct Blend {
    property: P,
    value: Vec<f64>,
}

/// `Object3D.animate(worldTime)` on `root` and everything reachable from it.
pub(crate) fn animate(root: &ObjRef, world_time: i32) -> Result<i32> {
    let mut objects = Vec::new();
    for_each_reachable(root, &mut |r| {
        objects.push(r.clone());
        true
    });
    let mut validity = i32::MAX;
    for obj in &objects {
        let tracks: Vec<ObjRef> = obj.borrow().tracks.iter().map(|t| t.0.clone()).collect();
        if tracks.is_empty() {
            continue;
        }
        let mut blends: Vec<Blend> = Vec::new();
        for t in tracks {
            let track = AnimationTrack(t);
            let (seq, property, controller) = {
                let d = track.d();
                (d.sequence.clone(), d.property, d.controller.clone())
            };
            let Some(ctrl) = controller else { continue };
            let c = ctrl.d().clone();
            if c.weight == 0.0 {
                continue;
            }
            if !c.in_interval(world_time) {
                if world_time < c.start {
                    validity = validity.min(span_to_world(c.start as f64 - world_time as f64));
                }
                continue;
            }
            let ts = c.position(world_time);
            let sd = seq.d();
            let keys = sd.valid_keys()?;
            let v = sd.sample(&keys, ts);
            // Validity: until the sampled value can change, or the interval ends.
            let mut v_world = if c.speed == 0.0 {
                f64::INFINITY
            } else {
                let dir = c.speed.signum() as f64;
                sd.constant_span(&keys, ts, dir) / (c.speed as f64).abs()
            };
            if c.start != c.end {
                v_world = v_world.min(c.end as f64 - world_time as f64);
            }
            validity = validity.min(span_to_world(v_world));
            let w = c.weight as f64;
            match blends.iter_mut().find(|b| b.property == property) {
                Some(b) => {
                    if b.value.len() < v.len() {
                        b.value.resize(v.len(), 0.0);
                    }
                    for (acc, x) in b.value.iter_mut().zip(&v) {
                        *acc += w * x;
                    }
                }
                None => blends.push(Blend {
                    property,
                    value: v.iter().map(|x| w * x).collect(),
                }),
            }
        }
        for b in blends {
            apply(obj, b.property, &b.value);
        }
    }
    Ok(validity)
}

fn unit(v: f64) -> f64 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, 1.0)
    }
}

fn to_byte(v: f64) -> u32 {
    (unit(v) * 255.0).round() as u32
}

fn set_rgb(c: u32, v: &[f64]) -> u32 {
    (c & 0xFF00_0000) | (to_byte(v[0]) << 16) | (to_byte(v[1]) << 8) | to_byte(v[2])
}

fn set_alpha(c: u32, a: f64) -> u32 {
    (c & 0x00FF_FFFF) | (to_byte(a) << 24)
}

fn clamp_f(v: f64, lo: f64, hi: f64) -> f32 {
    if v.is_nan() {
        lo as f32
    } else {
        v.clamp(lo, hi) as f32
    }
}

fn round_i(v: f64, lo: i32, hi: i32) -> i32 {
    if v.is_nan() {
        0
    } else {
        v.round().clamp(lo as f64, hi as f64) as i32
    }
}

/// The smallest positive float (for the "≤ 0 → smallest positive" clamps).
const TINY: f32 = f32::MIN_POSITIVE;

/// Writes one blended property value into `obj`, mapped to its valid range (never fails).
fn apply(obj: &ObjRef, property: P, v: &[f64]) {
    let mut i = obj.borrow_mut();
    let i = &mut *i;
    if let Some(t) = &i.tf {
        // The fields are written directly below: mark the cached transforms dirty.
        t.cache.invalidate();
    }
    match property {
        P::Translation if i.tf.is_some() => {
            i.tf.as_mut().unwrap().translation = Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32);
            return;
        }
        P::Scale if i.tf.is_some() => {
            let s = if v.len() >= 3 {
                Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32)
            } else {
                Vec3::splat(v[0] as f32)
            };
            i.tf.as_mut().unwrap().scale = s;
            return;
        }
        P::Orientation if i.tf.is_some() => {
            let len = v.iter().map(|x| x * x).sum::<f64>().sqrt();
            // A zero (or non-finite) blended quaternion cannot be normalized: identity.
            let q = if len > 1e-30 && len.is_finite() {
                Quat::from_xyzw(
                    (v[0] / len) as f32,
                    (v[1] / len) as f32,
                    (v[2] / len) as f32,
                    (v[3] / len) as f32,
                )
            } else {
                Quat::IDENTITY
            };
            i.tf.as_mut().unwrap().orientation = q;
            return;
        }
        P::Alpha | P::Pickability | P::Visibility if i.node.is_some() => {
            let n = i.node.as_mut().unwrap();
            match property {
                P::Alpha => n.alpha = unit(v[0]) as f32,
                P::Pickability => n.picking = v[0] >= 0.5,
                _ => n.rendering = v[0] >= 0.5,
            }
            return;
        }
        _ => {}
    }
    match &mut i.kind {
        Kind::Camera(c) => {
            let persp = c.projection == Projection::Perspective;
            if c.projection == Projection::Generic {
                return;
            }
            let x = v[0] as f32;
            let positive = |x: f32| if x > 0.0 { x } else { TINY };
            match property {
                P::FieldOfView if persp => {
                    c.params[0] = if x.is_nan() || x <= 0.0 {
                        TINY
                    } else if x >= 180.0 {
                        f32::from_bits(180.0f32.to_bits() - 1)
                    } else {
                        x
                    }
                }
                P::FieldOfView => c.params[0] = positive(x),
                P::NearDistance if persp => c.params[2] = positive(x),
                P::NearDistance => c.params[2] = x,
                P::FarDistance if persp => c.params[3] = positive(x),
                P::FarDistance => c.params[3] = x,
                _ => {}
            }
        }
        Kind::Light(l) => match property {
            P::Color => l.color = set_rgb(l.color, v) & 0xFF_FFFF,
            P::Intensity => l.intensity = v[0] as f32,
            P::SpotAngle => l.spot_angle = clamp_f(v[0], 0.0, 90.0),
            P::SpotExponent => l.spot_exponent = clamp_f(v[0], 0.0, 128.0),
            _ => {}
        },
        Kind::Material(m) => match property {
            P::Alpha => m.diffuse = set_alpha(m.diffuse, v[0]),
            P::AmbientColor => m.ambient = set_rgb(m.ambient, v) & 0xFF_FFFF,
            P::DiffuseColor => m.diffuse = set_rgb(m.diffuse, v),
            P::EmissiveColor => m.emissive = set_rgb(m.emissive, v) & 0xFF_FFFF,
            P::SpecularColor => m.specular = set_rgb(m.specular, v) & 0xFF_FFFF,
            P::Shininess => m.shininess = clamp_f(v[0], 0.0, 128.0),
            _ => {}
        },
        Kind::Fog(f) => match property {
            P::Color => f.color = set_rgb(f.color, v) & 0xFF_FFFF,
            P::Density => f.density = clamp_f(v[0], 0.0, f64::MAX),
            P::NearDistance => f.near = v[0] as f32,
            P::FarDistance => f.far = v[0] as f32,
            _ => {}
        },
        Kind::Background(b) => match property {
            P::Alpha => b.color = set_alpha(b.color, v[0]),
            P::Color => b.color = set_rgb(b.color, v),
            P::Crop => {
                let big = i32::MAX / 2;
                b.crop[0] = round_i(v[0], -big, big);
                b.crop[1] = round_i(v[1], -big, big);
                if v.len() >= 4 {
                    b.crop[2] = round_i(v[2], 0, big);
                    b.crop[3] = round_i(v[3], 0, big);
                }
            }
            _ => {}
        },
        Kind::Sprite(s) if property == P::Crop => {
            let big = i32::MAX / 2;
            let n = MAX_SPRITE_CROP_DIMENSION;
            s.crop[0] = round_i(v[0], -big, big);
            s.crop[1] = round_i(v[1], -big, big);
            if v.len() >= 4 {
                s.crop[2] = round_i(v[2], -n, n);
                s.crop[3] = round_i(v[3], -n, n);
            }
        }
        Kind::Texture2D(t) if property == P::Color => {
            t.blend_color = set_rgb(t.blend_color, v) & 0xFF_FFFF;
        }
        Kind::VertexBuffer(vb) => match property {
            P::Alpha => vb.default_color = set_alpha(vb.default_color, v[0]),
            P::Color => vb.default_color = set_rgb(vb.default_color, v),
            _ => {}
        },
        Kind::Mesh(m) if property == P::MorphWeights => {
            if let Some(w) = m.ext.morph_weights_mut() {
                for (k, x) in w.iter_mut().enumerate() {
                    *x = v.get(k).map_or(0.0, |&y| y as f32);
                }
            }
        }
        _ => {}
    }
    i.gen = i.gen.wrapping_add(1);
}
