//! M3G animation (KeyframeSequence, AnimationTrack, AnimationController, Object3D.animate),
//! MorphingMesh and SkinnedMesh, against hand-computed values.

use m3g::*;

type KS = KeyframeSequence;
type AT = AnimationTrack;

fn is_iae<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IllegalArgument(_)))
}
fn is_ise<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IllegalState(_)))
}
fn is_ioobe<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::IndexOutOfBounds(_)))
}
fn is_ae<T: std::fmt::Debug>(r: Result<T>) -> bool {
    matches!(r, Err(Error::Arithmetic(_)))
}

fn close(a: f32, b: f32, eps: f32) -> bool {
    (a - b).abs() <= eps
}
fn assert_vec(a: &[f32], b: &[f32], eps: f32) {
    assert_eq!(a.len(), b.len(), "{a:?} vs {b:?}");
    for (x, y) in a.iter().zip(b) {
        assert!(close(*x, *y, eps), "{a:?} vs {b:?}");
    }
}

/// A sequence with `keys` (time, value), duration `d` and mode `mode`.
fn seq(
    interp: Interpolation,
    comps: usize,
    keys: &[(i32, &[f32])],
    d: i32,
    mode: RepeatMode,
) -> KS {
    let s = KS::new(keys.len(), comps, interp).unwrap();
    for (k, (t, v)) in keys.iter().enumerate() {
        s.set_keyframe(k, *t, v).unwrap();
    }
    s.set_duration(d).unwrap();
    s.set_repeat_mode(mode);
    s
}

fn at(s: &KS, t: f64) -> Vec<f32> {
    s.sample(t).unwrap()
}

fn quat_z(deg: f32) -> [f32; 4] {
    let h = (deg * 0.5).to_radians();
    [0.0, 0.0, h.sin(), h.cos()]
}

fn track(s: &KS, property: AnimationProperty, weight: f32) -> (AT, AnimationController) {
    let t = AT::new(s, property).unwrap();
    let c = AnimationController::new();
    c.set_weight(weight).unwrap();
    t.set_controller(Some(&c));
    (t, c)
}

// ---------------------------------------------------------------------------------------
// KeyframeSequence

#[test]
fn keyframe_sequence_constructor_and_setter_errors() {
    assert!(is_iae(KS::new(0, 1, Interpolation::Linear)));
    assert!(is_iae(KS::new(1, 0, Interpolation::Linear)));
    assert!(is_iae(Interpolation::from_raw(175)));
    assert!(is_iae(Interpolation::from_raw(181)));
    assert!(is_iae(KS::new(2, 3, Interpolation::Slerp)));
    assert!(is_iae(KS::new(2, 3, Interpolation::Squad)));
    let s = KS::new(3, 2, Interpolation::Spline).unwrap();
    assert_eq!(
        (
            s.keyframe_count(),
            s.component_count(),
            s.interpolation_type()
        ),
        (3, 2, Interpolation::Spline)
    );
    assert_eq!(s.repeat_mode(), RepeatMode::Constant);
    assert_eq!(s.duration(), 0);
    assert_eq!((s.valid_range_first(), s.valid_range_last()), (0, 2));
    assert_eq!(s.get_keyframe(1).unwrap(), (0, vec![0.0, 0.0]));
    assert!(is_ioobe(s.set_keyframe(3, 0, &[1.0, 2.0])));
    assert!(is_iae(s.set_keyframe(0, 0, &[1.0])));
    assert!(is_iae(s.set_keyframe(0, -1, &[1.0, 2.0])));
    assert!(is_ioobe(s.get_keyframe(3)));
    s.set_keyframe(2, 7, &[1.0, 2.0, 99.0]).unwrap();
    assert_eq!(s.get_keyframe(2).unwrap(), (7, vec![1.0, 2.0]));
    assert!(is_ioobe(s.set_valid_range(0, 3)));
    assert!(is_ioobe(s.set_valid_range(3, 0)));
    s.set_valid_range(2, 0).unwrap();
    assert_eq!((s.valid_range_first(), s.valid_range_last()), (2, 0));
    assert!(is_iae(s.set_duration(0)));
    assert!(is_iae(s.set_duration(-5)));
    assert!(is_iae(RepeatMode::from_raw(194)));
    // SLERP keys are normalized on set.
    let q = KS::new(1, 4, Interpolation::Slerp).unwrap();
    q.set_keyframe(0, 0, &[0.0, 0.0, 3.0, 4.0]).unwrap();
    assert_vec(&q.get_keyframe(0).unwrap().1, &[0.0, 0.0, 0.6, 0.8], 1e-6);
}

#[test]
fn deferred_sequence_errors_surface_in_animate() {
    let g = Group::new();
    let s = KS::new(2, 3, Interpolation::Linear).unwrap();
    let (t, _c) = track(&s, AnimationProperty::Translation, 1.0);
    g.add_animation_track(&t).unwrap();
    // Duration never set.
    assert!(is_ise(g.animate(0)));
    s.set_duration(100).unwrap();
    assert!(g.animate(0).is_ok());
    // Decreasing times in the valid range.
    s.set_keyframe(0, 50, &[0.0; 3]).unwrap();
    s.set_keyframe(1, 10, &[0.0; 3]).unwrap();
    assert!(is_ise(g.animate(0)));
    // ... but fine when the valid range wraps so they increase: 1 (10) then 0 (50).
    s.set_valid_range(1, 0).unwrap();
    assert!(g.animate(0).is_ok());
    // Duration less than the last valid key.
    s.set_duration(40).unwrap();
    assert!(is_ise(g.animate(0)));
    // An inactive track does not sample its sequence.
    t.set_controller(None);
    assert!(g.animate(0).is_ok());
}

#[test]
fn linear_constant_and_times_outside_the_keys() {
    let s = seq(
        Interpolation::Linear,
        1,
        &[(100, &[0.0]), (1100, &[10.0])],
        2000,
        RepeatMode::Constant,
    );
    assert_vec(&at(&s, 350.0), &[2.5], 1e-6);
    assert_vec(&at(&s, -1e6), &[0.0], 0.0);
    assert_vec(&at(&s, 99.0), &[0.0], 0.0);
    assert_vec(&at(&s, 1100.0), &[10.0], 0.0);
    assert_vec(&at(&s, 5000.0), &[10.0], 0.0);
}

#[test]
fn linear_loop_interpolates_across_the_wrap() {
    let s = seq(
        Interpolation::Linear,
        1,
        &[(100, &[0.0]), (600, &[10.0])],
        1000,
        RepeatMode::Loop,
    );
    assert_vec(&at(&s, 350.0), &[5.0], 1e-6);
    // 600 → 1100 (the first key of the next repeat): s = 200 / 500.
    assert_vec(&at(&s, 800.0), &[6.0], 1e-5);
    // Before the first key: the segment from the previous repeat's last key (−400).
    assert_vec(&at(&s, 50.0), &[1.0], 1e-5);
    assert_vec(&at(&s, 1050.0), &[1.0], 1e-5);
    assert_vec(&at(&s, -950.0), &[1.0], 1e-5);
    assert_vec(&at(&s, 3350.0), &[5.0], 1e-5);
}

#[test]
fn valid_range_limits_the_keys_used() {
    let s = seq(
        Interpolation::Linear,
        1,
        &[(0, &[100.0]), (10, &[0.0]), (20, &[10.0]), (30, &[100.0])],
        40,
        RepeatMode::Constant,
    );
    s.set_valid_range(1, 2).unwrap();
    assert_vec(&at(&s, 0.0), &[0.0], 0.0);
    assert_vec(&at(&s, 15.0), &[5.0], 1e-6);
    assert_vec(&at(&s, 35.0), &[10.0], 0.0);
    // A wrapping range: keys 3 (t 30) then 0 (t 0) decrease, which is invalid ...
    s.set_valid_range(3, 0).unwrap();
    assert!(is_ise(s.sample(0.0)));
    // ... unless the times are non-decreasing in range order.
    s.set_keyframe(0, 35, &[50.0]).unwrap();
    assert_vec(&at(&s, 32.5), &[75.0], 1e-5);
}

#[test]
fn step_uses_the_highest_coincident_key() {
    let s = seq(
        Interpolation::Step,
        1,
        &[(0, &[1.0]), (10, &[2.0]), (10, &[3.0]), (20, &[4.0])],
        30,
        RepeatMode::Constant,
    );
    assert_vec(&at(&s, 5.0), &[1.0], 0.0);
    assert_vec(&at(&s, 10.0), &[3.0], 0.0);
    assert_vec(&at(&s, 19.9), &[3.0], 0.0);
    assert_vec(&at(&s, 20.0), &[4.0], 0.0);
}

#[test]
fn keys_at_equal_times_make_a_discontinuity() {
    let s = seq(
        Interpolation::Linear,
        1,
        &[(0, &[0.0]), (10, &[5.0]), (10, &[20.0]), (20, &[30.0])],
        20,
        RepeatMode::Constant,
    );
    // The segment ending at 10 uses the lowest index there (5) ...
    assert_vec(&at(&s, 5.0), &[2.5], 1e-6);
    assert_vec(&at(&s, 9.999), &[5.0], 1e-2);
    // ... the one starting at 10 the highest (20).
    assert_vec(&at(&s, 10.0), &[20.0], 1e-6);
    assert_vec(&at(&s, 15.0), &[25.0], 1e-6);
    // In LOOP mode, a key at D coincides with the next repeat's key at 0.
    let l = seq(
        Interpolation::Linear,
        1,
        &[(0, &[0.0]), (10, &[10.0]), (10, &[100.0])],
        10,
        RepeatMode::Loop,
    );
    assert_vec(&at(&l, 5.0), &[5.0], 1e-6);
    assert_vec(&at(&l, 10.0), &[0.0], 1e-6);
    // All keys at one time: nothing to interpolate, no division by zero.
    let z = seq(
        Interpolation::Spline,
        1,
        &[(0, &[1.0]), (0, &[2.0]), (0, &[3.0])],
        1,
        RepeatMode::Constant,
    );
    assert_vec(&at(&z, -1.0), &[1.0], 0.0);
    assert_vec(&at(&z, 0.0), &[3.0], 0.0);
    let zl = seq(
        Interpolation::Spline,
        1,
        &[(0, &[1.0]), (0, &[2.0])],
        1,
        RepeatMode::Loop,
    );
    let v = at(&zl, 0.5)[0];
    assert!(v.is_finite());
}

#[test]
fn zero_duration_sequences() {
    // A duration of zero cannot be set, and an unset one is an error at animate time.
    let s = KS::new(1, 1, Interpolation::Linear).unwrap();
    assert!(is_iae(s.set_duration(0)));
    assert!(is_ise(s.sample(0.0)));
    // The shortest legal duration with keys at 0 and 1 in LOOP mode.
    let s = seq(
        Interpolation::Linear,
        1,
        &[(0, &[0.0]), (1, &[10.0])],
        1,
        RepeatMode::Loop,
    );
    assert_vec(&at(&s, 0.5), &[5.0], 1e-6);
    assert_vec(&at(&s, 7.25), &[2.5], 1e-5);
    // A single key: that value at every time.
    let one = seq(
        Interpolation::Spline,
        2,
        &[(5, &[1.0, 2.0])],
        10,
        RepeatMode::Loop,
    );
    assert_vec(&at(&one, -3.0), &[1.0, 2.0], 0.0);
    assert_vec(&at(&one, 123.0), &[1.0, 2.0], 0.0);
}

#[test]
fn spline_even_uneven_and_end_tangents() {
    // Even spacing: T⁰₁ = 15, T¹₂ = 10 ⇒ 20 + (15 − 10)/8.
    let s = seq(
        Interpolation::Spline,
        1,
        &[(0, &[0.0]), (10, &[10.0]), (20, &[30.0]), (30, &[30.0])],
        30,
        RepeatMode::Constant,
    );
    assert_vec(&at(&s, 15.0), &[20.625], 1e-5);
    // Uneven: F⁻₁ = 2·30/40 = 1.5, F⁺₂ = 2·30/40 = 1.5 ⇒ 20 + (22.5 − 15)/8.
    let u = seq(
        Interpolation::Spline,
        1,
        &[(0, &[0.0]), (10, &[10.0]), (40, &[30.0]), (50, &[30.0])],
        50,
        RepeatMode::Constant,
    );
    assert_vec(&at(&u, 25.0), &[20.9375], 1e-5);
    // First segment of a CONSTANT sequence: zero tangent at key 0; T¹₁ = 0.5·15.
    assert_vec(&at(&u, 5.0), &[4.0625], 1e-5);
    // Keys are interpolated exactly.
    assert_vec(&at(&u, 10.0), &[10.0], 1e-6);
    assert_vec(&at(&u, 40.0), &[30.0], 1e-6);
    // LOOP: neighbours wrap with times shifted by D. Segment 20 → 30 (key 0 again).
    let l = seq(
        Interpolation::Spline,
        1,
        &[(0, &[0.0]), (10, &[10.0]), (20, &[0.0])],
        30,
        RepeatMode::Loop,
    );
    assert_vec(&at(&l, 25.0), &[-1.25], 1e-5);
    assert_vec(&at(&l, -5.0), &[-1.25], 1e-5);
}

#[test]
fn slerp_does_not_take_the_shorter_path() {
    let s = seq(
        Interpolation::Slerp,
        4,
        &[(0, &quat_z(0.0)), (100, &quat_z(90.0))],
        100,
        RepeatMode::Constant,
    );
    assert_vec(&at(&s, 50.0), &quat_z(45.0), 1e-6);
    assert_vec(&at(&s, 25.0), &quat_z(22.5), 1e-6);
    // −q₁ is 135° away in quaternion space: the midpoint is a 135° rotation about −Z.
    let n = quat_z(90.0).map(|x| -x);
    let s = seq(
        Interpolation::Slerp,
        4,
        &[(0, &quat_z(0.0)), (100, &n)],
        100,
        RepeatMode::Constant,
    );
    assert_vec(&at(&s, 50.0), &[0.0, 0.0, -0.923_879_5, 0.382_683_4], 1e-5);
}

#[test]
fn slerp_between_q_and_minus_q() {
    let q = quat_z(60.0);
    let n = q.map(|x| -x);
    let s = seq(
        Interpolation::Slerp,
        4,
        &[(0, &q), (100, &n)],
        100,
        RepeatMode::Constant,
    );
    for t in [0.0, 1.0, 25.0, 50.0, 75.0, 99.9] {
        let v = at(&s, t);
        assert!(v.iter().all(|x| x.is_finite()), "{v:?}");
        let len: f32 = v.iter().map(|x| x * x).sum::<f32>().sqrt();
        assert!(close(len, 1.0, 1e-5), "{v:?}");
    }
    assert_vec(&at(&s, 0.0), &q, 1e-6);
    // Continuous towards −q.
    assert_vec(&at(&s, 99.999), &n, 1e-3);
    assert_vec(&at(&s, 100.0), &n, 0.0);
}

#[test]
fn slerp_between_nearly_opposite_quaternions() {
    let a = [0.0, 0.0, 0.0, 1.0];
    let b = [0.001, 0.0, 0.0, -1.0];
    let s = seq(
        Interpolation::Slerp,
        4,
        &[(0, &a), (100, &b)],
        100,
        RepeatMode::Constant,
    );
    // The great circle through a and b: the midpoint is ≈ (1, 0, 0, 0).
    let m = at(&s, 50.0);
    assert_vec(&m, &[1.0, 0.0, 0.0, 0.0], 1e-3);
    for t in [10.0, 50.0, 90.0] {
        let v = at(&s, t);
        let len: f32 = v.iter().map(|x| x * x).sum::<f32>().sqrt();
        assert!(close(len, 1.0, 1e-4), "{v:?}");
    }
}

#[test]
fn squad_with_zero_end_tangents_eases() {
    let s = seq(
        Interpolation::Squad,
        4,
        &[(0, &quat_z(0.0)), (100, &quat_z(90.0))],
        100,
        RepeatMode::Constant,
    );
    // a₀ = exp(−π/8·k) (−45°), b₁ = q₁·exp(π/8·k) (135°). At s = ¼:
    // slerp(⅜; rot 22.5°, identity) = rot 14.0625°.
    assert_vec(&at(&s, 25.0), &quat_z(14.0625), 1e-5);
    assert_vec(&at(&s, 50.0), &quat_z(45.0), 1e-5);
    assert_vec(&at(&s, 0.0), &quat_z(0.0), 1e-6);
    // Uniform rotation about one axis with even keys: SQUAD equals SLERP (tangents match).
    let keys: Vec<[f32; 4]> = (0..4).map(|k| quat_z(30.0 * k as f32)).collect();
    let u = seq(
        Interpolation::Squad,
        4,
        &[
            (0, &keys[0]),
            (10, &keys[1]),
            (20, &keys[2]),
            (30, &keys[3]),
        ],
        30,
        RepeatMode::Constant,
    );
    assert_vec(&at(&u, 15.0), &quat_z(45.0), 1e-5);
    assert_vec(&at(&u, 12.5), &quat_z(37.5), 1e-5);
}

// ---------------------------------------------------------------------------------------
// AnimationController and AnimationTrack

#[test]
fn controller_time_mapping() {
    let c = AnimationController::new();
    assert_eq!((c.active_interval_start(), c.active_interval_end()), (0, 0));
    assert_eq!((c.weight(), c.speed(), c.ref_world_time()), (1.0, 1.0, 0));
    c.set_position(0.0, 3000);
    c.set_speed(0.5, 3000);
    assert_eq!(c.position(5000), 1000.0);
    // setSpeed keeps the position at the given world time.
    let before = c.position(4200);
    c.set_speed(-2.0, 4200);
    assert_eq!(c.position(4200), before);
    assert_eq!(c.ref_world_time(), 4200);
    assert_eq!(c.position(4300), before - 200.0);
    assert!(is_iae(c.set_active_interval(10, 5)));
    c.set_active_interval(5, 10).unwrap();
    assert!(is_iae(c.set_weight(-0.1)));
}

#[test]
fn track_constructor_checks_property_and_components() {
    let s1 = KS::new(1, 1, Interpolation::Linear).unwrap();
    let s2 = KS::new(1, 2, Interpolation::Linear).unwrap();
    let s3 = KS::new(1, 3, Interpolation::Linear).unwrap();
    let s4 = KS::new(1, 4, Interpolation::Linear).unwrap();
    assert!(is_iae(AnimationProperty::from_raw(255)));
    assert!(is_iae(AnimationProperty::from_raw(277)));
    assert!(is_iae(AT::new(&s1, AnimationProperty::Translation)));
    assert!(is_iae(AT::new(&s3, AnimationProperty::Orientation)));
    assert!(is_iae(AT::new(&s2, AnimationProperty::Scale)));
    assert!(is_iae(AT::new(&s3, AnimationProperty::Crop)));
    assert!(is_iae(AT::new(&s3, AnimationProperty::Alpha)));
    assert!(AT::new(&s1, AnimationProperty::Scale).is_ok());
    assert!(AT::new(&s3, AnimationProperty::Scale).is_ok());
    assert!(AT::new(&s2, AnimationProperty::Crop).is_ok());
    assert!(AT::new(&s4, AnimationProperty::Crop).is_ok());
    assert!(AT::new(&s4, AnimationProperty::Orientation).is_ok());
    assert!(AT::new(&s3, AnimationProperty::MorphWeights).is_ok());
    let t = AT::new(&s3, AnimationProperty::Color).unwrap();
    assert!(t.controller().is_none());
    assert_eq!(t.keyframe_sequence(), s3);
    assert_eq!(t.target_property(), AnimationProperty::Color);
    // References: the sequence and the controller.
    let c = AnimationController::new();
    t.set_controller(Some(&c));
    assert_eq!(t.get_references().len(), 2);
}

#[test]
fn add_animation_track_checks_the_target_class() {
    let s1 = KS::new(1, 1, Interpolation::Linear).unwrap();
    let s3 = KS::new(1, 3, Interpolation::Linear).unwrap();
    let shin = AT::new(&s1, AnimationProperty::Shininess).unwrap();
    let g = Group::new();
    assert!(is_iae(g.add_animation_track(&shin)));
    assert!(Material::new().add_animation_track(&shin).is_ok());
    assert!(is_iae(CompositingMode::new().add_animation_track(
        &AT::new(&s1, AnimationProperty::Alpha).unwrap()
    )));
    assert!(is_iae(Appearance::new().add_animation_track(
        &AT::new(&s3, AnimationProperty::Color).unwrap()
    )));
    assert!(is_iae(g.add_animation_track(
        &AT::new(&s1, AnimationProperty::FieldOfView).unwrap()
    )));
    assert!(Camera::new()
        .add_animation_track(&AT::new(&s1, AnimationProperty::FieldOfView).unwrap())
        .is_ok());
    assert!(is_iae(g.add_animation_track(
        &AT::new(&s3, AnimationProperty::MorphWeights).unwrap()
    )));
    let vb = VertexBuffer::new();
    assert!(vb
        .add_animation_track(&AT::new(&s1, AnimationProperty::Alpha).unwrap())
        .is_ok());
    assert!(is_iae(vb.add_animation_track(
        &AT::new(&s3, AnimationProperty::Translation).unwrap()
    )));
    // Texture2D is Transformable and has a blend color.
    let img = Image2D::new(ImageFormat::Rgb, 4, 4).unwrap();
    let tex = Texture2D::new(&img).unwrap();
    assert!(tex
        .add_animation_track(&AT::new(&s3, AnimationProperty::Translation).unwrap())
        .is_ok());
    assert!(tex
        .add_animation_track(&AT::new(&s3, AnimationProperty::Color).unwrap())
        .is_ok());
    // Already attached; same property with another component count.
    let scale1 = AT::new(&s1, AnimationProperty::Scale).unwrap();
    g.add_animation_track(&scale1).unwrap();
    assert!(is_iae(g.add_animation_track(&scale1)));
    assert!(is_iae(g.add_animation_track(
        &AT::new(&s3, AnimationProperty::Scale).unwrap()
    )));
    assert!(g
        .add_animation_track(&AT::new(&s1, AnimationProperty::Scale).unwrap())
        .is_ok());
    assert_eq!(g.animation_track_count(), 2);
    g.remove_animation_track(Some(&scale1));
    g.remove_animation_track(Some(&scale1));
    g.remove_animation_track(None);
    assert_eq!(g.animation_track_count(), 1);
}

#[test]
fn blending_sums_weights_without_normalizing() {
    let g = Group::new();
    let a = seq(
        Interpolation::Linear,
        3,
        &[(0, &[2.0, 4.0, 8.0])],
        10,
        RepeatMode::Constant,
    );
    let b = seq(
        Interpolation::Linear,
        3,
        &[(0, &[100.0, 0.0, 0.0])],
        10,
        RepeatMode::Constant,
    );
    let (ta, _ca) = track(&a, AnimationProperty::Translation, 0.5);
    let (tb, cb) = track(&b, AnimationProperty::Translation, 0.25);
    g.add_animation_track(&ta).unwrap();
    g.add_animation_track(&tb).unwrap();
    g.animate(0).unwrap();
    assert_vec(&g.get_translation(), &[26.0, 2.0, 4.0], 1e-5);
    // A lone track with weight 0.5 yields half its value.
    cb.set_weight(0.0).unwrap();
    g.animate(0).unwrap();
    assert_vec(&g.get_translation(), &[1.0, 2.0, 4.0], 1e-6);
    // No active track: the value is kept.
    g.set_translation(7.0, 7.0, 7.0);
    cb.set_active_interval(100, 200).unwrap();
    ta.set_controller(None);
    g.animate(0).unwrap();
    assert_eq!(g.get_translation(), [7.0, 7.0, 7.0]);
}

#[test]
fn orientation_is_normalized_after_the_sum() {
    let g = Group::new();
    let a = seq(
        Interpolation::Slerp,
        4,
        &[(0, &quat_z(0.0))],
        10,
        RepeatMode::Constant,
    );
    let b = seq(
        Interpolation::Slerp,
        4,
        &[(0, &quat_z(90.0))],
        10,
        RepeatMode::Constant,
    );
    let (ta, ca) = track(&a, AnimationProperty::Orientation, 1.0);
    let (tb, _cb) = track(&b, AnimationProperty::Orientation, 1.0);
    g.add_animation_track(&ta).unwrap();
    g.add_animation_track(&tb).unwrap();
    g.animate(0).unwrap();
    assert_vec(&g.get_orientation_quat(), &quat_z(45.0), 1e-6);
    // A single track with weight 0.3 is still normalized.
    g.remove_animation_track(Some(&tb));
    ca.set_weight(0.3).unwrap();
    g.set_orientation(10.0, 1.0, 0.0, 0.0).unwrap();
    g.animate(0).unwrap();
    assert_vec(&g.get_orientation_quat(), &[0.0, 0.0, 0.0, 1.0], 1e-6);
}

#[test]
fn weights_summing_to_zero() {
    // Weights are ≥ 0, so they sum to 0 only when every one is 0: no active track, the
    // values are kept.
    let g = Group::new();
    let a = seq(
        Interpolation::Linear,
        3,
        &[(0, &[1.0, 2.0, 3.0])],
        10,
        RepeatMode::Constant,
    );
    let (ta, ca) = track(&a, AnimationProperty::Translation, 0.0);
    g.add_animation_track(&ta).unwrap();
    g.set_translation(5.0, 5.0, 5.0);
    assert_eq!(g.animate(0).unwrap(), i32::MAX);
    assert_eq!(g.get_translation(), [5.0, 5.0, 5.0]);
    ca.set_weight(1.0).unwrap();
    g.animate(0).unwrap();
    assert_eq!(g.get_translation(), [1.0, 2.0, 3.0]);
    // Quaternions that cancel (q and −q): the zero sum cannot be normalized: identity.
    let q = quat_z(90.0);
    let n = q.map(|x| -x);
    let s1 = seq(
        Interpolation::Linear,
        4,
        &[(0, &q)],
        10,
        RepeatMode::Constant,
    );
    let s2 = seq(
        Interpolation::Linear,
        4,
        &[(0, &n)],
        10,
        RepeatMode::Constant,
    );
    let (t1, _c1) = track(&s1, AnimationProperty::Orientation, 1.0);
    let (t2, _c2) = track(&s2, AnimationProperty::Orientation, 1.0);
    g.add_animation_track(&t1).unwrap();
    g.add_animation_track(&t2).unwrap();
    g.set_orientation(30.0, 0.0, 1.0, 0.0).unwrap();
    g.animate(0).unwrap();
    assert_vec(&g.get_orientation_quat(), &[0.0, 0.0, 0.0, 1.0], 0.0);
    // Morph weights that sum to 0 are legal: R = B + Σ wᵢ(Tᵢ − B).
    let (m, _) = morph_fixture();
    m.set_weights(&[1.0, -1.0]).unwrap();
    let vb = m.morphed_vertex_buffer().unwrap();
    let p = vb.get_positions().0.unwrap().get_shorts(0, 3).unwrap();
    // 10 + (20 − 10) − (40 − 10) = −10, ...
    assert_eq!(p, vec![-10, 0, 0, 0, -10, 0, 0, 0, 0]);
}

#[test]
fn active_interval_speed_and_validity() {
    let g = Group::new();
    let s = seq(
        Interpolation::Linear,
        3,
        &[(0, &[0.0; 3]), (1000, &[1000.0, 0.0, 0.0])],
        1000,
        RepeatMode::Constant,
    );
    let (t, c) = track(&s, AnimationProperty::Translation, 1.0);
    g.add_animation_track(&t).unwrap();
    c.set_active_interval(1000, 3000).unwrap();
    c.set_position(0.0, 1000);
    // Before the interval: nothing changes, valid until it starts.
    assert_eq!(g.animate(500).unwrap(), 500);
    assert_eq!(g.get_translation(), [0.0; 3]);
    // Inside: t_s = 500; the value changes continuously.
    assert_eq!(g.animate(1500).unwrap(), 0);
    assert_vec(&g.get_translation(), &[500.0, 0.0, 0.0], 1e-4);
    // Past the last key: constant until the interval ends.
    assert_eq!(g.animate(2500).unwrap(), 500);
    assert_vec(&g.get_translation(), &[1000.0, 0.0, 0.0], 0.0);
    // After the interval: inactive for good.
    assert_eq!(g.animate(3000).unwrap(), i32::MAX);
    // Half speed from world 1000.
    c.set_speed(0.5, 1000);
    g.animate(2000).unwrap();
    assert_vec(&g.get_translation(), &[500.0, 0.0, 0.0], 1e-4);
    // STEP: valid until the next key (in world time, / speed).
    let st = seq(
        Interpolation::Step,
        1,
        &[(0, &[0.2]), (100, &[0.8])],
        200,
        RepeatMode::Constant,
    );
    let g2 = Group::new();
    let (t2, c2) = track(&st, AnimationProperty::Alpha, 1.0);
    g2.add_animation_track(&t2).unwrap();
    c2.set_speed(0.5, 0);
    assert_eq!(g2.animate(50).unwrap(), 150);
    assert!(close(g2.alpha_factor(), 0.2, 1e-6));
    assert_eq!(g2.animate(200).unwrap(), i32::MAX);
    assert!(close(g2.alpha_factor(), 0.8, 1e-6));
    // No tracks at all.
    assert_eq!(Group::new().animate(0).unwrap(), i32::MAX);
}

#[test]
fn animate_reaches_every_referenced_object() {
    let world = World::new();
    let mat = Material::new();
    let app = Appearance::new();
    app.set_material(Some(&mat));
    let (vb, ib) = quad_vb();
    let mesh = Mesh::new(&vb, &ib, Some(&app));
    world.add_child(&mesh).unwrap();
    let s = seq(
        Interpolation::Linear,
        1,
        &[(0, &[0.0]), (100, &[100.0])],
        100,
        RepeatMode::Constant,
    );
    let (t, _c) = track(&s, AnimationProperty::Shininess, 1.0);
    mat.add_animation_track(&t).unwrap();
    world.animate(50).unwrap();
    assert!(close(mat.shininess(), 50.0, 1e-4));
    // Clamped to [0, 128].
    let s2 = seq(
        Interpolation::Linear,
        1,
        &[(0, &[500.0])],
        100,
        RepeatMode::Constant,
    );
    let (t2, _c2) = track(&s2, AnimationProperty::Shininess, 1.0);
    mat.add_animation_track(&t2).unwrap();
    world.animate(50).unwrap();
    assert_eq!(mat.shininess(), 128.0);
}

fn apply1(obj: &impl Object3DExt, property: AnimationProperty, v: &[f32]) {
    let s = seq(
        Interpolation::Linear,
        v.len(),
        &[(0, v)],
        10,
        RepeatMode::Constant,
    );
    let (t, _c) = track(&s, property, 1.0);
    obj.add_animation_track(&t).unwrap();
    obj.animate(0).unwrap();
    obj.remove_animation_track(Some(&t));
}

#[test]
fn every_property_is_applied_and_clamped() {
    // Node.
    let g = Group::new();
    apply1(&g, AnimationProperty::Alpha, &[1.7]);
    assert_eq!(g.alpha_factor(), 1.0);
    apply1(&g, AnimationProperty::Visibility, &[0.49]);
    assert!(!g.is_rendering_enabled());
    apply1(&g, AnimationProperty::Visibility, &[0.5]);
    assert!(g.is_rendering_enabled());
    apply1(&g, AnimationProperty::Pickability, &[0.2]);
    assert!(!g.is_picking_enabled());
    apply1(&g, AnimationProperty::Scale, &[2.0]);
    assert_eq!(g.get_scale(), [2.0; 3]);
    apply1(&g, AnimationProperty::Scale, &[1.0, 2.0, -3.0]);
    assert_eq!(g.get_scale(), [1.0, 2.0, -3.0]);
    apply1(&g, AnimationProperty::Translation, &[1.0, 2.0, 3.0]);
    assert_eq!(g.get_translation(), [1.0, 2.0, 3.0]);
    apply1(&g, AnimationProperty::Orientation, &[0.0, 0.0, 2.0, 0.0]);
    assert_vec(&g.get_orientation_quat(), &[0.0, 0.0, 1.0, 0.0], 1e-6);
    // Camera: perspective clamps; generic is untouched.
    let cam = Camera::new();
    cam.set_perspective(60.0, 1.0, 1.0, 100.0).unwrap();
    apply1(&cam, AnimationProperty::FieldOfView, &[200.0]);
    let fov = cam.get_projection_params().1.unwrap()[0];
    assert!(fov < 180.0 && fov > 179.99);
    apply1(&cam, AnimationProperty::FieldOfView, &[-1.0]);
    assert!(cam.get_projection_params().1.unwrap()[0] > 0.0);
    apply1(&cam, AnimationProperty::NearDistance, &[-5.0]);
    apply1(&cam, AnimationProperty::FarDistance, &[50.0]);
    let p = cam.get_projection_params().1.unwrap();
    assert!(p[2] > 0.0 && p[2] < 1e-30 && p[3] == 50.0);
    cam.set_parallel(2.0, 1.0, 1.0, 10.0).unwrap();
    apply1(&cam, AnimationProperty::NearDistance, &[-5.0]);
    apply1(&cam, AnimationProperty::FieldOfView, &[0.0]);
    let p = cam.get_projection_params().1.unwrap();
    assert_eq!(p[2], -5.0);
    assert!(p[0] > 0.0);
    // Light.
    let l = Light::new();
    apply1(&l, AnimationProperty::Color, &[1.5, 0.5, -1.0]);
    assert_eq!(l.color(), Color(0x00FF_8000));
    apply1(&l, AnimationProperty::Intensity, &[-2.5]);
    assert_eq!(l.intensity(), -2.5);
    apply1(&l, AnimationProperty::SpotAngle, &[100.0]);
    assert_eq!(l.spot_angle(), 90.0);
    apply1(&l, AnimationProperty::SpotExponent, &[-1.0]);
    assert_eq!(l.spot_exponent(), 0.0);
    // Material.
    let m = Material::new();
    apply1(&m, AnimationProperty::Alpha, &[0.0]);
    assert_eq!(m.color(MaterialColor::DIFFUSE).unwrap(), Color(0x00CC_CCCC));
    apply1(&m, AnimationProperty::DiffuseColor, &[1.0, 0.0, 0.0]);
    assert_eq!(m.color(MaterialColor::DIFFUSE).unwrap(), Color(0x00FF_0000));
    apply1(&m, AnimationProperty::AmbientColor, &[0.0, 1.0, 0.0]);
    assert_eq!(m.color(MaterialColor::AMBIENT).unwrap(), Color(0x0000_FF00));
    apply1(&m, AnimationProperty::EmissiveColor, &[0.0, 0.0, 1.0]);
    assert_eq!(
        m.color(MaterialColor::EMISSIVE).unwrap(),
        Color(0x0000_00FF)
    );
    apply1(&m, AnimationProperty::SpecularColor, &[0.2, 0.2, 0.2]);
    assert_eq!(
        m.color(MaterialColor::SPECULAR).unwrap(),
        Color(0x0033_3333)
    );
    // Fog.
    let f = Fog::new();
    apply1(&f, AnimationProperty::Density, &[-1.0]);
    assert_eq!(f.density(), 0.0);
    apply1(&f, AnimationProperty::NearDistance, &[-3.0]);
    apply1(&f, AnimationProperty::FarDistance, &[30.0]);
    assert_eq!((f.near_distance(), f.far_distance()), (-3.0, 30.0));
    apply1(&f, AnimationProperty::Color, &[1.0, 1.0, 0.0]);
    assert_eq!(f.color(), Color(0x00FF_FF00));
    // Background.
    let b = Background::new();
    apply1(&b, AnimationProperty::Color, &[1.0, 0.0, 0.0]);
    apply1(&b, AnimationProperty::Alpha, &[0.5]);
    assert_eq!(b.color(), Color(0x80FF_0000));
    apply1(&b, AnimationProperty::Crop, &[1.4, -2.6, -5.0, 7.0]);
    assert_eq!(
        (b.crop_x(), b.crop_y(), b.crop_width(), b.crop_height()),
        (1, -3, 0, 7)
    );
    // Sprite3D: width and height clamped to ±maxSpriteCropDimension; 2 components = x, y.
    let img = Image2D::new(ImageFormat::Rgb, 8, 8).unwrap();
    let sp = Sprite3D::new(true, &img, None);
    apply1(&sp, AnimationProperty::Crop, &[2.0, 3.0, -5000.0, 5000.0]);
    assert_eq!(
        (sp.crop_x(), sp.crop_y(), sp.crop_width(), sp.crop_height()),
        (2, 3, -MAX_SPRITE_CROP_DIMENSION, MAX_SPRITE_CROP_DIMENSION)
    );
    apply1(&sp, AnimationProperty::Crop, &[4.0, 5.0]);
    assert_eq!(
        (sp.crop_x(), sp.crop_y(), sp.crop_width()),
        (4, 5, -MAX_SPRITE_CROP_DIMENSION)
    );
    // Texture2D blend color and transform.
    let tex = Texture2D::new(&img).unwrap();
    apply1(&tex, AnimationProperty::Color, &[0.0, 1.0, 1.0]);
    assert_eq!(tex.blend_color(), Color(0x0000_FFFF));
    apply1(&tex, AnimationProperty::Translation, &[0.5, 0.0, 0.0]);
    assert_eq!(tex.get_translation(), [0.5, 0.0, 0.0]);
    // VertexBuffer default color.
    let vb = VertexBuffer::new();
    apply1(&vb, AnimationProperty::Color, &[0.0, 0.0, 1.0]);
    apply1(&vb, AnimationProperty::Alpha, &[0.0]);
    assert_eq!(vb.default_color(), Color(0x0000_00FF));
    // MorphingMesh weights: V < N fills with 0, V > N ignores the rest.
    let (mm, _) = morph_fixture();
    mm.set_weights(&[0.3, 0.3]).unwrap();
    apply1(&mm, AnimationProperty::MorphWeights, &[0.5]);
    assert_eq!(mm.weights(), vec![0.5, 0.0]);
    apply1(&mm, AnimationProperty::MorphWeights, &[0.1, 0.2, 0.3]);
    assert_vec(&mm.weights(), &[0.1, 0.2], 1e-7);
}

// ---------------------------------------------------------------------------------------
// MorphingMesh

fn quad_vb() -> (VertexBuffer, IndexBuffer) {
    let va = VertexArray::new(4, 3, 2).unwrap();
    va.set_shorts(0, &[-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0])
        .unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 1.0, None).unwrap();
    let ib = TriangleStripArray::new_explicit(&[0, 1, 3, 2], &[4])
        .unwrap()
        .as_index_buffer();
    (vb, ib)
}

fn positions_vb(p: &[i16], colors: Option<&[u8]>, default: u32) -> VertexBuffer {
    let n = p.len() / 3;
    let va = VertexArray::new(n, 3, 2).unwrap();
    va.set_shorts(0, p).unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 0.5, Some(&[1.0, 2.0, 3.0]))
        .unwrap();
    if let Some(c) = colors {
        let ca = VertexArray::new(n, 3, 1).unwrap();
        ca.set_ubytes(0, c).unwrap();
        vb.set_colors(Some(&ca)).unwrap();
    }
    vb.set_default_color(Color(default));
    vb
}

/// Base positions (10,0,0) (0,10,0) (0,0,0); targets ×2 and ×4.
fn morph_fixture() -> (MorphingMesh, Vec<VertexBuffer>) {
    let base = positions_vb(
        &[10, 0, 0, 0, 10, 0, 0, 0, 0],
        Some(&[100, 0, 0, 0, 100, 0, 0, 0, 100]),
        0xFF00_0000,
    );
    let t1 = positions_vb(&[20, 0, 0, 0, 20, 0, 0, 0, 0], None, 0xFF20_0000);
    let t2 = positions_vb(&[40, 0, 0, 0, 40, 0, 0, 0, 0], None, 0x0040_0000);
    let ib = TriangleStripArray::new_implicit(0, &[3])
        .unwrap()
        .as_index_buffer();
    let m = MorphingMesh::new(&base, &[t1.clone(), t2.clone()], &ib, None).unwrap();
    (m, vec![base, t1, t2])
}

#[test]
fn morphing_mesh_api() {
    let (m, vbs) = morph_fixture();
    assert_eq!(m.morph_target_count(), 2);
    assert_eq!(m.morph_target(1).unwrap(), vbs[2]);
    assert!(is_ioobe(m.morph_target(2)));
    assert_eq!(m.weights(), vec![0.0, 0.0]);
    assert!(is_iae(m.set_weights(&[1.0])));
    m.set_weights(&[0.25, 0.5, 99.0]).unwrap();
    assert_eq!(m.weights(), vec![0.25, 0.5]);
    assert_eq!(m.as_mesh().vertex_buffer(), vbs[0]);
    assert_eq!(Object3D::from(&m).class_name(), "MorphingMesh");
    assert!(Object3D::from(&m).downcast::<Mesh>().is_some());
    assert!(Object3D::from(&m).downcast::<SkinnedMesh>().is_none());
    // References: the base, the submesh and the targets.
    let refs = m.get_references();
    assert!(refs.contains(&Object3D::from(&vbs[1])));
    assert!(refs.contains(&Object3D::from(&vbs[2])));
    let (vb, ib) = quad_vb();
    assert!(is_iae(MorphingMesh::new(&vb, &[], &ib, None)));
}

#[test]
fn morph_equation_with_weights_not_summing_to_one() {
    let (m, vbs) = morph_fixture();
    // Weights 0: the base.
    let out = m.morphed_vertex_buffer().unwrap();
    let pos = |vb: &VertexBuffer| vb.get_positions().0.unwrap().get_shorts(0, 3).unwrap();
    assert_eq!(pos(&out), vec![10, 0, 0, 0, 10, 0, 0, 0, 0]);
    // Scale and bias come from the base.
    assert_eq!(out.get_positions().1, [0.5, 1.0, 2.0, 3.0]);
    // 10 + 0.5·10 + 1.5·30 = 60 (sum of weights 2).
    m.set_weights(&[0.5, 1.5]).unwrap();
    let out = m.morphed_vertex_buffer().unwrap();
    assert_eq!(pos(&out), vec![60, 0, 0, 0, 60, 0, 0, 0, 0]);
    // Negative weights: 10 − 0.5·10 = 5.
    m.set_weights(&[-0.5, 0.0]).unwrap();
    assert_eq!(
        pos(&m.morphed_vertex_buffer().unwrap()),
        vec![5, 0, 0, 0, 5, 0, 0, 0, 0]
    );
    // Colors are not in the targets: shared with the base. The default color is morphed:
    // A 255 + (−0.5)(255 − 255) = 255, R 0 + (−0.5)(0x20) → clamped to 0.
    let out = m.morphed_vertex_buffer().unwrap();
    assert_eq!(out.colors().unwrap(), vbs[0].colors().unwrap());
    m.set_weights(&[0.5, 0.25]).unwrap();
    let out = m.morphed_vertex_buffer().unwrap();
    // A: 255 + 0.25·(0 − 255) = 191.25; R: 0.5·0x20 + 0.25·0x40 = 32.
    assert_eq!(out.default_color(), Color(0xBF20_0000));
}

#[test]
fn morph_targets_with_colors_and_deferred_errors() {
    let base = positions_vb(&[0, 0, 0, 10, 0, 0], Some(&[0, 0, 0, 200, 200, 200]), 0);
    let t = positions_vb(
        &[10, 10, 10, 10, 0, 0],
        Some(&[255, 100, 0, 100, 200, 250]),
        0,
    );
    let ib = TriangleStripArray::new_implicit(0, &[3])
        .unwrap()
        .as_index_buffer();
    let m = MorphingMesh::new(&base, std::slice::from_ref(&t), &ib, None).unwrap();
    m.set_weights(&[0.5]).unwrap();
    let out = m.morphed_vertex_buffer().unwrap();
    let c = out.colors().unwrap().get_bytes(0, 2).unwrap();
    let c: Vec<u8> = c.iter().map(|&x| x as u8).collect();
    assert_eq!(c, vec![128, 50, 0, 150, 200, 225]);
    // Overflowing colors clamp.
    m.set_weights(&[3.0]).unwrap();
    let c = m
        .morphed_vertex_buffer()
        .unwrap()
        .colors()
        .unwrap()
        .get_bytes(0, 1)
        .unwrap();
    assert_eq!(
        c.iter().map(|&x| x as u8).collect::<Vec<_>>(),
        vec![255, 255, 0]
    );
    // A target with an array the base lacks: IllegalState at deformation (render/pick).
    let na = VertexArray::new(2, 3, 1).unwrap();
    t.set_normals(Some(&na)).unwrap();
    assert!(is_ise(m.morphed_vertex_buffer()));
    base.set_normals(Some(&na)).unwrap();
    assert!(m.morphed_vertex_buffer().is_ok());
    // Targets that differ from each other.
    let t2 = positions_vb(&[10, 10, 10, 10, 0, 0], None, 0);
    let m2 = MorphingMesh::new(&base, &[t.clone(), t2], &ib, None).unwrap();
    assert!(is_ise(m2.morphed_vertex_buffer()));
}

#[test]
fn morphing_is_recomputed_only_when_an_input_changes() {
    let (m, vbs) = morph_fixture();
    m.set_weights(&[0.5, 0.0]).unwrap();
    m.morphed_vertex_buffer().unwrap();
    m.morphed_vertex_buffer().unwrap();
    assert_eq!(m.deform_count(), 1);
    m.set_weights(&[0.5, 0.0]).unwrap();
    m.morphed_vertex_buffer().unwrap();
    assert_eq!(m.deform_count(), 1);
    m.set_weights(&[0.5, 0.1]).unwrap();
    m.morphed_vertex_buffer().unwrap();
    assert_eq!(m.deform_count(), 2);
    // Editing a target's array.
    vbs[1]
        .get_positions()
        .0
        .unwrap()
        .set_shorts(0, &[30, 0, 0])
        .unwrap();
    let out = m.morphed_vertex_buffer().unwrap();
    assert_eq!(m.deform_count(), 3);
    // 10 + 0.5·20 + 0.1·30 = 23.
    assert_eq!(
        out.get_positions().0.unwrap().get_shorts(0, 1).unwrap(),
        vec![23, 0, 0]
    );
    // Rendering uses (and does not recompute) the same buffer.
    let (g, img) = target(8);
    let mut g = g;
    g.render_node(&m, None).unwrap();
    g.release_target();
    let _ = img;
    assert_eq!(m.deform_count(), 3);
}

// ---------------------------------------------------------------------------------------
// SkinnedMesh

fn target(size: i32) -> (Graphics3D, Image2D) {
    let img = Image2D::new(ImageFormat::Rgb, size, size).unwrap();
    let mut g = Graphics3D::new();
    g.bind_image(&img, true, RenderHints::empty()).unwrap();
    g.clear(None).unwrap();
    let c = Camera::new();
    c.set_parallel(2.0, 1.0, -10.0, 10.0).unwrap();
    g.set_camera(Some(&c), None).unwrap();
    (g, img)
}

/// Three vertices on the X axis at 0, 1, 2, with +Z normals.
fn skin_fixture() -> (SkinnedMesh, Group, Group, Group) {
    let va = VertexArray::new(3, 3, 2).unwrap();
    va.set_shorts(0, &[0, 0, 0, 1, 0, 0, 2, 0, 0]).unwrap();
    let na = VertexArray::new(3, 3, 2).unwrap();
    na.set_shorts(0, &[0, 0, 32767, 0, 0, 32767, 0, 0, 32767])
        .unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 1.0, None).unwrap();
    vb.set_normals(Some(&na)).unwrap();
    let ib = TriangleStripArray::new_implicit(0, &[3])
        .unwrap()
        .as_index_buffer();
    let skeleton = Group::new();
    let b0 = Group::new();
    let b1 = Group::new();
    b1.set_translation(1.0, 0.0, 0.0);
    skeleton.add_child(&b0).unwrap();
    b0.add_child(&b1).unwrap();
    let m = SkinnedMesh::new(&vb, &ib, None, &skeleton).unwrap();
    (m, skeleton, b0, b1)
}

#[test]
fn skinned_mesh_construction_and_add_transform_errors() {
    let (m, skel, b0, b1) = skin_fixture();
    assert_eq!(m.skeleton(), skel);
    assert_eq!(skel.parent().unwrap(), m.as_node());
    assert_eq!(Object3D::from(&m).class_name(), "SkinnedMesh");
    assert!(m.get_references().contains(&Object3D::from(&skel)));
    // The skeleton cannot be adopted elsewhere.
    assert!(is_iae(Group::new().add_child(&skel)));
    let (vb, ib) = quad_vb();
    assert!(is_iae(SkinnedMesh::new(&vb, &ib, None, &skel)));
    assert!(is_iae(SkinnedMesh::new(
        &vb,
        &ib,
        None,
        &World::new().as_group()
    )));
    let other = Group::new();
    assert!(is_iae(m.add_transform(&other.as_node(), 1, 0, 1)));
    assert!(is_iae(m.add_transform(&b0.as_node(), 0, 0, 1)));
    assert!(is_iae(m.add_transform(&b0.as_node(), 1, 0, 0)));
    assert!(is_ioobe(m.add_transform(&b0.as_node(), 1, 65535, 1)));
    assert!(m.add_transform(&skel.as_node(), 1, 0, 1).is_ok());
    assert!(m.add_transform(&b1.as_node(), 1, 1, 2).is_ok());
    assert!(is_iae(m.get_bone_transform(&other.as_node())));
    assert!(is_iae(m.get_bone_vertices(&other.as_node())));
    // At rest: mesh → bone 1 is a translation by −1.
    let t = m.get_bone_transform(&b1.as_node()).unwrap().get();
    assert_eq!(t[3], -1.0);
    // A vertex range past the vertex count: IllegalState when skinning (render/pick).
    m.add_transform(&b0.as_node(), 1, 2, 5).unwrap();
    assert!(is_ise(m.skinned_vertices()));
    let (mut g, _img) = target(4);
    assert!(is_ise(g.render_node(&m, None)));
    g.release_target();
}

#[test]
fn skinning_blends_bone_transforms() {
    let (m, _skel, b0, b1) = skin_fixture();
    // Vertex 0: bone 0 only; vertex 1: bones 0 and 1 (weights 1 : 3); vertex 2: bone 1.
    m.add_transform(&b0.as_node(), 1, 0, 2).unwrap();
    m.add_transform(&b1.as_node(), 3, 1, 2).unwrap();
    let (p, _) = m.skinned_vertices().unwrap();
    assert_vec(
        &p.concat(),
        &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0, 0.0, 0.0],
        1e-6,
    );
    // Move bone 1 up by 4 and rotate bone 0 by 90° about Z (bone 1 follows it).
    b1.translate(0.0, 4.0, 0.0);
    let (p, _) = m.skinned_vertices().unwrap();
    // v1 = ¼·(1,0,0) + ¾·(1,4,0) = (1, 3, 0); v2 = (2, 4, 0).
    assert_vec(
        &p.concat(),
        &[0.0, 0.0, 0.0, 1.0, 3.0, 0.0, 2.0, 4.0, 0.0],
        1e-5,
    );
    b1.translate(0.0, -4.0, 0.0);
    b0.set_orientation(90.0, 0.0, 0.0, 1.0).unwrap();
    let (p, n) = m.skinned_vertices().unwrap();
    assert_vec(
        &p.concat(),
        &[0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0, 0.0],
        1e-5,
    );
    // Normals along Z stay along Z under a rotation about Z.
    for nv in n.unwrap() {
        assert_vec(&nv, &[0.0, 0.0, 1.0], 1e-4);
    }
    // Rotating about Y turns the normals: bone 0 by 90° about Y maps +Z to +X.
    b0.set_orientation(90.0, 0.0, 1.0, 0.0).unwrap();
    let (_, n) = m.skinned_vertices().unwrap();
    for nv in n.unwrap() {
        assert_vec(&nv, &[1.0, 0.0, 0.0], 1e-4);
    }
    // Bone vertices: normalized weights.
    let (idx, w) = m.get_bone_vertices(&b1.as_node()).unwrap();
    assert_eq!(idx, vec![1, 2]);
    assert_vec(&w, &[0.75, 1.0], 1e-6);
    let (idx, w) = m.get_bone_vertices(&b0.as_node()).unwrap();
    assert_eq!(idx, vec![0, 1]);
    assert_vec(&w, &[1.0, 0.25], 1e-6);
}

#[test]
fn skinning_keeps_the_top_weights_and_skinned_buffer_is_cached() {
    let (m, skel, b0, b1) = skin_fixture();
    let extra: Vec<Group> = (0..4)
        .map(|k| {
            let g = Group::new();
            g.set_translation(0.0, 10.0 * (k + 1) as f32, 0.0);
            skel.add_child(&g).unwrap();
            g
        })
        .collect();
    // Vertex 0 gets six bones; the four highest weights act.
    m.add_transform(&b0.as_node(), 1, 0, 1).unwrap();
    m.add_transform(&b1.as_node(), 1, 0, 1).unwrap();
    for (k, g) in extra.iter().enumerate() {
        m.add_transform(&g.as_node(), 2 + k as i32, 0, 1).unwrap();
    }
    assert_eq!(
        m.get_bone_vertices(&b0.as_node()).unwrap().0,
        Vec::<usize>::new()
    );
    let (_, w) = m.get_bone_vertices(&extra[3].as_node()).unwrap();
    assert_vec(&w, &[5.0 / 14.0], 1e-6);
    // The skinned buffer is recomputed only when a bone moves.
    let (vb, _) = m
        .skinned_vertices()
        .map(|_| (m.skinned_vertex_buffer().unwrap(), ()))
        .unwrap();
    m.skinned_vertex_buffer().unwrap();
    assert_eq!(m.deform_count(), 1);
    extra[0].translate(0.0, 0.0, 1.0);
    let vb2 = m.skinned_vertex_buffer().unwrap();
    assert_eq!(m.deform_count(), 2);
    assert_eq!(vb, vb2);
    // Quantized positions decode to the float result.
    let (p, _) = m.skinned_vertices().unwrap();
    let (arr, sb) = vb2.get_positions();
    let raw = arr.unwrap().get_shorts(0, 3).unwrap();
    for v in 0..3 {
        for c in 0..3 {
            let x = raw[v * 3 + c] as f32 * sb[0] + sb[1 + c];
            assert!(close(x, p[v][c], 1e-3), "{x} vs {}", p[v][c]);
        }
    }
}

#[test]
fn bones_with_zero_scale() {
    let (m, _skel, b0, b1) = skin_fixture();
    // A zero-scale bone has no at-rest transform.
    b1.set_scale(0.0, 0.0, 0.0);
    assert!(is_ae(m.add_transform(&b1.as_node(), 1, 0, 3)));
    b1.set_scale(1.0, 1.0, 1.0);
    m.add_transform(&b1.as_node(), 1, 1, 2).unwrap();
    m.add_transform(&b0.as_node(), 1, 0, 2).unwrap();
    // Scaled to zero afterwards: its vertices collapse onto the bone's origin, and the
    // normals stay finite (the singular bone contributes none).
    b1.set_scale(0.0, 0.0, 0.0);
    let (p, n) = m.skinned_vertices().unwrap();
    // v1 = ½·(1,0,0) [bone 0] + ½·(1,0,0) [bone 1's origin] ; v2 = (1, 0, 0).
    assert_vec(
        &p.concat(),
        &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0],
        1e-6,
    );
    for nv in n.unwrap() {
        assert!(nv.iter().all(|x| x.is_finite()));
        assert_vec(&nv, &[0.0, 0.0, 1.0], 1e-4);
    }
    let vb = m.skinned_vertex_buffer().unwrap();
    assert!(vb.get_positions().1.iter().all(|x| x.is_finite()));
    // All vertices on one bone scaled to zero: a degenerate bounding box still encodes.
    let (m2, _s2, _c0, c1) = skin_fixture();
    m2.add_transform(&c1.as_node(), 1, 0, 3).unwrap();
    c1.set_scale(0.0, 0.0, 0.0);
    let vb = m2.skinned_vertex_buffer().unwrap();
    let (arr, sb) = vb.get_positions();
    assert_eq!(arr.unwrap().get_shorts(0, 3).unwrap(), vec![0; 9]);
    assert_eq!(&sb[1..], &[1.0, 0.0, 0.0]);
}

#[test]
fn skinned_mesh_renders_deformed_and_its_skeleton() {
    // A quad whose right half follows a bone moved right; a sprite-free child mesh on the
    // bone is drawn too.
    let va = VertexArray::new(4, 3, 2).unwrap();
    va.set_shorts(0, &[-1, -1, 0, 0, -1, 0, 0, 1, 0, -1, 1, 0])
        .unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 0.5, None).unwrap();
    vb.set_default_color(Color(0xFFFF_0000));
    let ib = TriangleStripArray::new_explicit(&[0, 1, 3, 2], &[4])
        .unwrap()
        .as_index_buffer();
    let skel = Group::new();
    let bone = Group::new();
    skel.add_child(&bone).unwrap();
    let app = Appearance::new();
    let pm = PolygonMode::new();
    pm.set_culling(Culling::None);
    app.set_polygon_mode(Some(&pm));
    let m = SkinnedMesh::new(&vb, &ib, Some(&app), &skel).unwrap();
    m.add_transform(&bone.as_node(), 1, 1, 2).unwrap();
    let world = World::new();
    world.add_child(&m).unwrap();
    let cam = Camera::new();
    cam.set_parallel(2.0, 1.0, -10.0, 10.0).unwrap();
    world.add_child(&cam).unwrap();
    world.set_active_camera(&cam);
    // Animate the bone to x + 0.5 at t = 1000.
    let s = seq(
        Interpolation::Linear,
        3,
        &[(0, &[0.0, 0.0, 0.0]), (1000, &[0.5, 0.0, 0.0])],
        1000,
        RepeatMode::Constant,
    );
    let (t, _c) = track(&s, AnimationProperty::Translation, 1.0);
    bone.add_animation_track(&t).unwrap();
    let render = |time: i32| -> Vec<u8> {
        world.animate(time).unwrap();
        let img = Image2D::new(ImageFormat::Rgb, 8, 8).unwrap();
        let mut g = Graphics3D::new();
        g.bind_image(&img, true, RenderHints::empty()).unwrap();
        g.render_world(&world).unwrap();
        g.release_target();
        img.pixels()
    };
    let red_cols =
        |px: &[u8]| -> Vec<usize> { (0..8).filter(|&x| px[(4 * 8 + x) * 3] > 128).collect() };
    // t = 0: x ∈ [−0.5, 0] → columns 2..3.
    assert_eq!(red_cols(&render(0)), vec![2, 3]);
    // t = 1000: x ∈ [−0.5, 0.5] → columns 2..5.
    assert_eq!(red_cols(&render(1000)), vec![2, 3, 4, 5]);
    // A mesh under the bone is drawn as a normal branch.
    let (qvb, qib) = quad_vb();
    qvb.set_default_color(Color(0xFF00_FF00));
    let small = Mesh::new(&qvb, &qib, Some(&app));
    small.set_scale(0.25, 0.25, 0.25);
    small.set_translation(0.0, 0.75, 0.0);
    bone.add_child(&small).unwrap();
    let px = render(0);
    let at = (8 + 4) * 3;
    assert_eq!(&px[at..at + 3], &[0, 255, 0]);
    // Picking sees the deformed mesh.
    world.animate(1000).unwrap();
    let hit = world.pick(-1, 0.7, 0.5, &cam).unwrap().unwrap();
    assert_eq!(hit.intersected(), Some(m.as_node()));
}

#[test]
fn duplicate_copies_the_skeleton_and_remaps_bones() {
    let (m, skel, _b0, b1) = skin_fixture();
    m.add_transform(&b1.as_node(), 1, 0, 3).unwrap();
    let copy = m.duplicate();
    let cs = copy.skeleton();
    assert!(cs != skel);
    assert_eq!(cs.parent().unwrap(), copy.as_node());
    // Moving the original bone does not move the copy.
    b1.translate(0.0, 5.0, 0.0);
    let (p, _) = copy.skinned_vertices().unwrap();
    assert_vec(&p[2], &[2.0, 0.0, 0.0], 1e-6);
    let (p, _) = m.skinned_vertices().unwrap();
    assert_vec(&p[2], &[2.0, 5.0, 0.0], 1e-6);
    // The copy's bone is the copied node.
    let cb1 = cs
        .child(0)
        .unwrap()
        .downcast::<Group>()
        .unwrap()
        .child(0)
        .unwrap();
    assert_eq!(copy.get_bone_vertices(&cb1).unwrap().0, vec![0, 1, 2]);
}

// ---------------------------------------------------------------------------------------
// Corpus: the animated and skinned files against the reference images, with the tolerance of
// tests/data/m3g/reference/MANIFEST.md (a pixel fails when some channel is off by more
// than 8; at most 1 % of pixels may fail, and the mean channel difference is at most 1).

#[path = "common/corpus.rs"]
mod corpus;

#[test]
fn corpus_animated_files_match_the_reference_at_three_times() {
    let Some(dir) = corpus::m3g_corpus() else {
        return;
    };
    for file in ["desktop-m3g-skinned", "robot"] {
        let roots = match loader::Loader::load_path(dir.join(format!("{file}.m3g"))) {
            Ok(r) => r,
            Err(e) => panic!("{file}: load failed: {e:?}"),
        };
        for t in [0, 1000, 2500] {
            let reference = dir.join(format!("reference/{file}_t{t}.png"));
            let img = image::open(&reference).expect("reference image");
            let img = img.to_rgb8();
            let (w, h) = img.dimensions();
            let ours = loader::render_roots(&roots, t, w, h, false, loader::RenderTarget::Graphics)
                .unwrap_or_else(|e| panic!("{file} t={t}: render failed: {e}"));
            let (mut gt1, mut gt8, mut sum, mut max) = (0usize, 0usize, 0u64, 0u8);
            for (a, b) in ours.chunks(3).zip(img.as_raw().chunks(3)) {
                let d = (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap();
                sum += (0..3).map(|c| a[c].abs_diff(b[c]) as u64).sum::<u64>();
                gt1 += (d > 1) as usize;
                gt8 += (d > 8) as usize;
                max = max.max(d);
            }
            let n = (w * h) as f64;
            eprintln!(
                "CORPUS {file}_t{t}: px>1 {gt1} ({:.3}%), px>8 {gt8} ({:.3}%), max {max}, mean abs {:.3}",
                100.0 * gt1 as f64 / n,
                100.0 * gt8 as f64 / n,
                sum as f64 / (3.0 * n)
            );
            assert!(
                gt8 as f64 <= 0.01 * n && sum as f64 / (3.0 * n) <= 1.0,
                "{file} t={t} is outside the corpus tolerance"
            );
        }
    }
}
