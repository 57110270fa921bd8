//! `KeyframeSequence`: time-stamped keyframes and their interpolation (STEP, LINEAR,
//! SLERP, SPLINE, SQUAD) in CONSTANT or LOOP mode.
//!
//! Sampling works on the *valid* keys only, laid out in valid-range order (a range with
//! `last < first` wraps around the index space). In LOOP mode the valid keys are treated as
//! replicated at every multiple of the duration: an "extended index" `e = n·M + k` stands
//! for valid key `k` of repeat `n` at time `t_k + n·D`, so the segment from the last key to
//! the first key of the next repeat is an ordinary segment, and spline neighbours wrap with
//! their times shifted by ±D. All arithmetic is done in f64.

use super::error::{iae, ioobe, ise, Result};
use super::modes::{Interpolation, RepeatMode};
use super::object::{class_data, handle, Inner, Kind};

#[derive(Clone, Debug)]
pub(crate) struct KeyframeData {
    pub interpolation: Interpolation,
    pub comps: usize,
    pub times: Vec<i32>,
    pub values: Vec<Vec<f32>>,
    pub repeat: RepeatMode,
    /// 0 = not set (a set duration is always > 0).
    pub duration: i32,
    pub first: usize,
    pub last: usize,
}

handle!(
    /// `KeyframeSequence`: vector-valued keyframes sampled by [`AnimationTrack`]s.
    ///
    /// [`AnimationTrack`]: super::AnimationTrack
    KeyframeSequence,
    |i| matches!(i.kind, Kind::KeyframeSequence(_))
);
class_data!(KeyframeSequence, KeyframeSequence, KeyframeData);

impl KeyframeSequence {
    /// `KeyframeSequence(numKeyframes, numComponents, interpolation)`: every key the zero
    /// vector at time 0, CONSTANT, duration unset, valid range all keys. IllegalArgument if a
    /// count is < 1 or SLERP/SQUAD has ≠ 4 components.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// // A color going from red to blue in one second, then back again.
    /// let colors = KeyframeSequence::new(2, 3, Interpolation::Linear)?;
    /// colors.set_keyframe(0, 0, &[1.0, 0.0, 0.0])?;
    /// colors.set_keyframe(1, 1000, &[0.0, 0.0, 1.0])?;
    /// colors.set_duration(2000)?;
    /// colors.set_repeat_mode(RepeatMode::Loop);
    /// assert_eq!(colors.sample(500.0)?, [0.5, 0.0, 0.5]);
    /// assert_eq!(colors.sample(1500.0)?, [0.5, 0.0, 0.5]); // wrapping back to red
    /// # Ok(())
    /// # }
    /// ```
    pub fn new(
        num_keyframes: usize,
        num_components: usize,
        interpolation: Interpolation,
    ) -> Result<Self> {
        if num_keyframes < 1 || num_components < 1 {
            return iae("keyframe and component counts must be at least 1");
        }
        if interpolation.is_quaternion() && num_components != 4 {
            return iae("SLERP and SQUAD need 4 components");
        }
        let (n, c) = (num_keyframes, num_components);
        Ok(KeyframeSequence(Inner::new(
            Kind::KeyframeSequence(KeyframeData {
                interpolation,
                comps: c,
                times: vec![0; n],
                values: vec![vec![0.0; c]; n],
                repeat: RepeatMode::Constant,
                duration: 0,
                first: 0,
                last: n - 1,
            }),
            false,
            false,
        )))
    }

    /// `getComponentCount()`.
    pub fn component_count(&self) -> usize {
        self.d().comps
    }
    /// `getKeyframeCount()`.
    pub fn keyframe_count(&self) -> usize {
        self.d().times.len()
    }
    /// `getInterpolationType()`.
    pub fn interpolation_type(&self) -> Interpolation {
        self.d().interpolation
    }

    /// `setKeyframe(index, time, value)`: the first `numComponents` values are copied
    /// (SLERP/SQUAD keys are normalized; a zero quaternion stays zero). IndexOutOfBounds for a
    /// bad index; IllegalArgument for a negative time or a short `value`.
    pub fn set_keyframe(&self, index: usize, time: i32, value: &[f32]) -> Result<()> {
        let mut d = self.dm();
        if index >= d.times.len() {
            return ioobe("keyframe index");
        }
        if value.len() < d.comps {
            return iae("value shorter than the component count");
        }
        if time < 0 {
            return iae("negative keyframe time");
        }
        let mut v = value[..d.comps].to_vec();
        if d.interpolation.is_quaternion() {
            let len = v.iter().map(|&x| x as f64 * x as f64).sum::<f64>().sqrt();
            if len > 0.0 && len.is_finite() {
                v.iter_mut().for_each(|x| *x = (*x as f64 / len) as f32);
            }
        }
        d.times[index] = time;
        d.values[index] = v;
        Ok(())
    }

    /// `getKeyframe(index, value)`: the time and the (for SLERP/SQUAD normalized) value.
    /// IndexOutOfBounds for a bad index.
    pub fn get_keyframe(&self, index: usize) -> Result<(i32, Vec<f32>)> {
        let d = self.d();
        if index >= d.times.len() {
            return ioobe("keyframe index");
        }
        Ok((d.times[index], d.values[index].clone()))
    }

    /// `setValidRange(first, last)`: `last < first` wraps around. IndexOutOfBounds unless
    /// both are below the keyframe count.
    pub fn set_valid_range(&self, first: usize, last: usize) -> Result<()> {
        let mut d = self.dm();
        let n = d.times.len();
        if first >= n || last >= n {
            return ioobe("valid range outside the keyframes");
        }
        d.first = first;
        d.last = last;
        Ok(())
    }
    /// `getValidRangeFirst()`.
    pub fn valid_range_first(&self) -> usize {
        self.d().first
    }
    /// `getValidRangeLast()`.
    pub fn valid_range_last(&self) -> usize {
        self.d().last
    }

    /// `setDuration(d)`: IllegalArgument unless d > 0.
    pub fn set_duration(&self, duration: i32) -> Result<()> {
        if duration <= 0 {
            return iae("duration must be positive");
        }
        self.dm().duration = duration;
        Ok(())
    }
    /// `getDuration()`: 0 while unset.
    pub fn duration(&self) -> i32 {
        self.d().duration
    }

    /// `setRepeatMode(mode)`.
    pub fn set_repeat_mode(&self, mode: RepeatMode) {
        self.dm().repeat = mode;
    }
    /// `getRepeatMode()`.
    pub fn repeat_mode(&self) -> RepeatMode {
        self.d().repeat
    }

    /// The interpolated value at sequence time `t` (a Rust extension: what an
    /// AnimationTrack samples). IllegalState for an invalid sequence (duration unset or
    /// shorter than the last valid key, or valid key times decreasing).
    pub fn sample(&self, t: f64) -> Result<Vec<f32>> {
        let d = self.d();
        let keys = d.valid_keys()?;
        Ok(d.sample(&keys, t).into_iter().map(|x| x as f32).collect())
    }
}

/// A valid key: time and value.
pub(crate) struct Key {
    pub t: f64,
    pub v: Vec<f64>,
}

impl KeyframeData {
    /// The valid keys in valid-range order, after the deferred validity checks.
    pub fn valid_keys(&self) -> Result<Vec<Key>> {
        if self.duration <= 0 {
            return ise("the keyframe sequence has no duration");
        }
        let n = self.times.len();
        let idx: Vec<usize> = if self.first <= self.last {
            (self.first..=self.last).collect()
        } else {
            (self.first..n).chain(0..=self.last).collect()
        };
        let keys: Vec<Key> = idx
            .iter()
            .map(|&i| Key {
                t: self.times[i] as f64,
                v: self.values[i].iter().map(|&x| x as f64).collect(),
            })
            .collect();
        if keys.windows(2).any(|w| w[1].t < w[0].t) {
            return ise("keyframe times decrease within the valid range");
        }
        if keys.last().unwrap().t > self.duration as f64 {
            return ise("the duration is less than the last valid keyframe time");
        }
        Ok(keys)
    }

    fn looping(&self) -> bool {
        self.repeat == RepeatMode::Loop
    }

    /// Key at extended index `e` (LOOP: any integer; CONSTANT: only [0, M)).
    fn ext<'a>(&self, keys: &'a [Key], e: i64) -> (f64, &'a [f64]) {
        let m = keys.len() as i64;
        let k = e.rem_euclid(m);
        let n = e.div_euclid(m);
        let key = &keys[k as usize];
        (key.t + n as f64 * self.duration as f64, &key.v)
    }

    fn has(&self, keys: &[Key], e: i64) -> bool {
        self.looping() || (0..keys.len() as i64).contains(&e)
    }

    /// The segment containing `t`: extended index `e` of its start key and the time
    /// reduced for LOOP. `None` in CONSTANT mode outside the keys (value = an end key).
    fn segment(&self, keys: &[Key], t: f64) -> (Option<i64>, f64, Option<usize>) {
        let m = keys.len() as i64;
        if self.looping() {
            let dur = self.duration as f64;
            let t = t.rem_euclid(dur);
            let t = if t >= dur { 0.0 } else { t };
            // Max e with time(e) ≤ t: time(-M) = t0 − D ≤ 0 ≤ t and time(M) = t0 + D > t.
            let mut e = m - 1;
            while e > -m && self.ext(keys, e).0 > t {
                e -= 1;
            }
            (Some(e), t, None)
        } else if t < keys[0].t {
            (None, t, Some(0))
        } else if t >= keys[m as usize - 1].t {
            (None, t, Some(m as usize - 1))
        } else {
            // Highest index with t_i ≤ t: a segment starts at the highest coincident key.
            let e = (0..m).rev().find(|&e| keys[e as usize].t <= t).unwrap();
            (Some(e), t, None)
        }
    }

    /// The value at sequence time `t` from the valid keys.
    pub fn sample(&self, keys: &[Key], t: f64) -> Vec<f64> {
        if keys.len() == 1 {
            return keys[0].v.clone();
        }
        let (seg, t, end) = self.segment(keys, t);
        let Some(e) = seg else {
            return keys[end.unwrap()].v.clone();
        };
        let (t0, v0) = self.ext(keys, e);
        let (t1, v1) = self.ext(keys, e + 1);
        if self.interpolation == Interpolation::Step {
            return v0.to_vec();
        }
        let s = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0);
        match self.interpolation {
            Interpolation::Linear => v0
                .iter()
                .zip(v1)
                .map(|(a, b)| (1.0 - s) * a + s * b)
                .collect(),
            Interpolation::Slerp => slerp(s, q4(v0), q4(v1)).to_vec(),
            Interpolation::Spline => {
                let tan0 = self.tangent(keys, e, true);
                let tan1 = self.tangent(keys, e + 1, false);
                let (s2, s3) = (s * s, s * s * s);
                let h = [
                    2.0 * s3 - 3.0 * s2 + 1.0,
                    -2.0 * s3 + 3.0 * s2,
                    s3 - 2.0 * s2 + s,
                    s3 - s2,
                ];
                (0..v0.len())
                    .map(|c| h[0] * v0[c] + h[1] * v1[c] + h[2] * tan0[c] + h[3] * tan1[c])
                    .collect()
            }
            _ => self.squad(keys, e, s).to_vec(),
        }
    }

    /// The tangent-scaling factor of key `e`: F⁻ (leaving) or F⁺ (arriving); 0 at the ends
    /// of a CONSTANT sequence.
    fn factor(&self, keys: &[Key], e: i64, leaving: bool) -> f64 {
        if !self.has(keys, e - 1) || !self.has(keys, e + 1) {
            return 0.0;
        }
        let (tp, _) = self.ext(keys, e - 1);
        let (ti, _) = self.ext(keys, e);
        let (tn, _) = self.ext(keys, e + 1);
        let span = tn - tp;
        if span <= 0.0 {
            return 0.0;
        }
        if leaving {
            2.0 * (tn - ti) / span
        } else {
            2.0 * (ti - tp) / span
        }
    }

    /// SPLINE: T⁰ (leaving, `leaving = true`) or T¹ (arriving) of key `e`.
    fn tangent(&self, keys: &[Key], e: i64, leaving: bool) -> Vec<f64> {
        let f = self.factor(keys, e, leaving);
        let (_, vi) = self.ext(keys, e);
        if f == 0.0 {
            return vec![0.0; vi.len()];
        }
        let (_, vp) = self.ext(keys, e - 1);
        let (_, vn) = self.ext(keys, e + 1);
        vp.iter().zip(vn).map(|(p, n)| f * (n - p) * 0.5).collect()
    }

    /// SQUAD between keys `e` and `e + 1` at `s`.
    fn squad(&self, keys: &[Key], e: i64, s: f64) -> [f64; 4] {
        let q = |e: i64| q4(self.ext(keys, e).1);
        let (qi, qn) = (q(e), q(e + 1));
        // a_i = q_i·exp((T⁰_i − log(q_i⁻¹ q_(i+1))) / 2)
        let log_next_i = qlog(qmul(qinv(qi), qn));
        let t0 = self.squad_tangent(keys, e, true);
        let a = qmul(qi, qexp(scale3(sub3(t0, log_next_i), 0.5)));
        // b_(i+1) = q_(i+1)·exp((log(q_i⁻¹ q_(i+1)) − T¹_(i+1)) / 2)
        let t1 = self.squad_tangent(keys, e + 1, false);
        let b = qmul(qn, qexp(scale3(sub3(log_next_i, t1), 0.5)));
        slerp(2.0 * s * (1.0 - s), slerp(s, qi, qn), slerp(s, a, b))
    }

    fn squad_tangent(&self, keys: &[Key], e: i64, leaving: bool) -> [f64; 3] {
        let f = self.factor(keys, e, leaving);
        if f == 0.0 {
            return [0.0; 3];
        }
        let q = |e: i64| q4(self.ext(keys, e).1);
        let (qp, qi, qn) = (q(e - 1), q(e), q(e + 1));
        let t = add3(qlog(qmul(qinv(qi), qn)), qlog(qmul(qinv(qp), qi)));
        scale3(t, 0.5 * f)
    }

    /// The sequence-time span from `t` during which the sampled value cannot change when
    /// time moves in direction `dir` (±1): `f64::INFINITY` when it never changes, 0 when it
    /// changes continuously.
    pub fn constant_span(&self, keys: &[Key], t: f64, dir: f64) -> f64 {
        if keys.len() == 1 {
            return f64::INFINITY;
        }
        let (seg, tr, end) = self.segment(keys, t);
        let step = self.interpolation == Interpolation::Step;
        match (seg, end) {
            (None, Some(0)) if dir > 0.0 => keys[0].t - t,
            (None, Some(0)) => f64::INFINITY,
            (None, _) if dir > 0.0 => f64::INFINITY,
            (None, _) => {
                let last = keys[keys.len() - 1].t;
                if t > last {
                    t - last
                } else {
                    0.0
                }
            }
            (Some(e), _) if step => {
                let (t0, _) = self.ext(keys, e);
                let (t1, _) = self.ext(keys, e + 1);
                if dir > 0.0 {
                    t1 - tr
                } else if tr > t0 {
                    // Moving back reaches t0 (still this key) and changes just below it.
                    tr - t0
                } else {
                    0.0
                }
            }
            _ => 0.0,
        }
    }
}

fn q4(v: &[f64]) -> [f64; 4] {
    [v[0], v[1], v[2], v[3]]
}

/// Quaternions are (x, y, z, w).
fn qmul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    let [ax, ay, az, aw] = a;
    let [bx, by, bz, bw] = b;
    [
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    ]
}

fn qinv(q: [f64; 4]) -> [f64; 4] {
    let n = q.iter().map(|x| x * x).sum::<f64>();
    if n == 0.0 {
        return [0.0, 0.0, 0.0, 1.0];
    }
    [-q[0] / n, -q[1] / n, -q[2] / n, q[3] / n]
}

/// The logarithm of a unit quaternion: the 3-vector axis·angle/2.
fn qlog(q: [f64; 4]) -> [f64; 3] {
    let vlen = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    if vlen < 1e-12 {
        return [0.0; 3];
    }
    let theta = vlen.atan2(q[3]);
    let k = theta / vlen;
    [q[0] * k, q[1] * k, q[2] * k]
}

fn qexp(v: [f64; 3]) -> [f64; 4] {
    let theta = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if theta < 1e-12 {
        return [v[0], v[1], v[2], 1.0];
    }
    let k = theta.sin() / theta;
    [v[0] * k, v[1] * k, v[2] * k, theta.cos()]
}

fn add3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn scale3(a: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] * k, a[1] * k, a[2] * k]
}

/// `slerp(s; a, b) = (a·sin((1−s)θ) + b·sin(sθ)) / sin θ`, θ the angle between a and b,
/// without flipping either to take the shorter path. Nearly equal quaternions fall back to
/// linear interpolation. Opposite quaternions (q and −q, where the great circle is
/// undefined) rotate through a fixed quaternion perpendicular to `a`, so the result is
/// continuous, unit length and deterministic.
pub(crate) fn slerp(s: f64, a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    let la = a.iter().map(|x| x * x).sum::<f64>().sqrt();
    let lb = b.iter().map(|x| x * x).sum::<f64>().sqrt();
    if la == 0.0 || lb == 0.0 {
        return std::array::from_fn(|k| (1.0 - s) * a[k] + s * b[k]);
    }
    let cos = (a.iter().zip(&b).map(|(x, y)| x * y).sum::<f64>() / (la * lb)).clamp(-1.0, 1.0);
    let theta = cos.acos();
    let sin = theta.sin();
    if sin < 1e-9 {
        if cos > 0.0 {
            return std::array::from_fn(|k| (1.0 - s) * a[k] + s * b[k]);
        }
        // b = −a (up to length): a half-turn along a fixed great circle through a.
        let p = [-a[1], a[0], -a[3], a[2]];
        let (c, sn) = (
            (s * std::f64::consts::PI).cos(),
            (s * std::f64::consts::PI).sin(),
        );
        let len = (1.0 - s) * la + s * lb;
        return std::array::from_fn(|k| (a[k] / la * c + p[k] / la * sn) * len);
    }
    let wa = ((1.0 - s) * theta).sin() / sin;
    let wb = (s * theta).sin() / sin;
    std::array::from_fn(|k| wa * a[k] + wb * b[k])
}

impl Interpolation {
    /// SLERP and SQUAD, which interpolate unit quaternions.
    pub(crate) fn is_quaternion(self) -> bool {
        matches!(self, Interpolation::Slerp | Interpolation::Squad)
    }
}
