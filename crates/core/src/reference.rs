//! The reference renderer: plain, slow f64 code that follows the specification literally,
//! fed the same [`RenderState`] and [`DrawCall`] as the fast pipeline. It shares nothing
//! with the fast path but the input types, so tests and benchmarks can measure the fast
//! path's error against it (ARCHITECTURE decision 6).
//!
//! Literal means: vertices transformed in f64, clipped in homogeneous space, window
//! coordinates *not* snapped, coverage sampled at pixel centers with a top-left rule on the
//! exact edge functions, attributes interpolated perspective-correctly per pixel, depth
//! interpolated linearly in window space and quantized with `round(z · (2ⁿ − 1))`.

use glam::DVec4;

use super::state::{CullFace, RenderState, ShadeModel, TexGen, Winding};
use super::target::Target;
use super::vertex::{DrawCall, Primitive};
use super::TEXTURE_UNITS;

mod compare;
mod fragment;
mod lines_points;
pub(crate) mod texturing;
pub use compare::{compare, ErrorStats};

#[derive(Clone, Copy, Debug)]
struct Vtx {
    pos: DVec4,
    color: DVec4,
    /// Texture coordinates per unit after the texture matrix, and eye-space z (for fog).
    tex: [DVec4; TEXTURE_UNITS],
    eye_z: f64,
}

fn lerp(a: &Vtx, b: &Vtx, t: f64) -> Vtx {
    Vtx {
        pos: a.pos + (b.pos - a.pos) * t,
        color: a.color + (b.color - a.color) * t,
        tex: std::array::from_fn(|u| a.tex[u] + (b.tex[u] - a.tex[u]) * t),
        eye_z: a.eye_z + (b.eye_z - a.eye_z) * t,
    }
}

/// Clips a polygon against −w ≤ x, y, z ≤ w and w > 0, one plane at a time.
fn clip(poly: Vec<Vtx>) -> Vec<Vtx> {
    let planes: [fn(DVec4) -> f64; 7] = [
        |p| p.w + p.x,
        |p| p.w - p.x,
        |p| p.w + p.y,
        |p| p.w - p.y,
        |p| p.w + p.z,
        |p| p.w - p.z,
        |p| p.w - 1e-300,
    ];
    let mut poly = poly;
    for d in planes {
        let mut out = Vec::with_capacity(poly.len() + 1);
        for i in 0..poly.len() {
            let (a, b) = (&poly[i], &poly[(i + 1) % poly.len()]);
            let (da, db) = (d(a.pos), d(b.pos));
            if da >= 0.0 {
                out.push(*a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                out.push(lerp(a, b, da / (da - db)));
            }
        }
        poly = out;
        if poly.len() < 3 {
            return Vec::new();
        }
    }
    poly
}

/// Renders `draws` with `state` both ways, each onto a copy of `base`: the fast pipeline
/// (on `threads` threads) and this reference. Returns both images and the fast one's error.
pub fn measure(
    state: &RenderState,
    draws: &[DrawCall<'_>],
    base: &Target,
    threads: usize,
) -> (Target, Target, ErrorStats) {
    let (mut fast, mut slow) = (base.clone(), base.clone());
    let mut frame = super::Frame::new(base.width(), base.height(), base.format());
    for d in draws {
        // Out of memory leaves the fast image short, which the error then shows.
        let _ = super::record(state, d, &mut frame);
        render(state, d, &mut slow);
    }
    frame.flush(&mut fast, threads);
    let e = compare(&fast, &slow);
    (fast, slow, e)
}

/// Renders `draw` into `target` the literal way.
pub fn render(state: &RenderState, draw: &DrawCall<'_>, target: &mut Target) {
    let mv = state.modelview.as_dmat4();
    let mvp = state.projection.as_dmat4() * mv;
    let fetch = |i: usize| {
        let p = DVec4::from_array(draw.position.fetch(i).map(f64::from));
        Vtx {
            pos: mvp * p,
            color: DVec4::from_array(draw.color.fetch(i).map(f64::from))
                .clamp(DVec4::ZERO, DVec4::ONE),
            tex: std::array::from_fn(|u| {
                let tc = match state.texgen[u] {
                    None => DVec4::from_array(draw.texcoord[u].fetch(i).map(f64::from)),
                    Some(g) => {
                        // The eye-space normal: the inverse transpose of the modelview.
                        let [nx, ny, nz, _] = draw.normal.fetch(i).map(f64::from);
                        let n = glam::DVec3::new(nx, ny, nz);
                        let m = glam::DMat3::from_mat4(mv).inverse().transpose();
                        let mut n = m * n;
                        if state.normalize || state.rescale_normal {
                            n = n.normalize_or_zero();
                        }
                        match g {
                            TexGen::NormalMap => n.extend(1.0),
                            TexGen::ReflectionMap => {
                                let e = (mv * p).truncate().normalize_or_zero();
                                let n = n.normalize_or_zero();
                                (e - 2.0 * n * n.dot(e)).extend(1.0)
                            }
                        }
                    }
                };
                state.texture_matrices[u].as_dmat4() * tc
            }),
            eye_z: (mv * p).z,
        }
    };
    let prim = draw.primitive;
    if prim == Primitive::Points {
        for k in 0..draw.indices.len() {
            let v = fetch(draw.indices.get(k));
            let p = v.pos;
            let inside = [
                p.w + p.x,
                p.w - p.x,
                p.w + p.y,
                p.w - p.y,
                p.w + p.z,
                p.w - p.z,
            ]
            .iter()
            .all(|&d| d >= 0.0)
                && p.w > 0.0;
            if inside {
                lines_points::point(state, &v, target);
            }
        }
    } else if prim.is_line() {
        prim.for_each_line(&draw.indices, |a, b| {
            let (va, vb) = (fetch(a), fetch(b));
            if let Some((ca, cb)) = clip_line(va, vb) {
                lines_points::line(state, &ca, &cb, vb.color, target);
            }
        });
    } else {
        prim.for_each_triangle(&draw.indices, |a, b, c| {
            let provoking = fetch(c);
            let poly = clip(vec![fetch(a), fetch(b), provoking]);
            for i in 1..poly.len().saturating_sub(1) {
                triangle(
                    state,
                    [poly[0], poly[i], poly[i + 1]],
                    provoking.color,
                    target,
                );
            }
        });
    }
}

/// Clips a segment against the clip volume and w > 0 by the parameter range inside every
/// plane.
fn clip_line(a: Vtx, b: Vtx) -> Option<(Vtx, Vtx)> {
    let d = |p: DVec4| {
        [
            p.w + p.x,
            p.w - p.x,
            p.w + p.y,
            p.w - p.y,
            p.w + p.z,
            p.w - p.z,
            p.w - 1e-300,
        ]
    };
    let (da, db) = (d(a.pos), d(b.pos));
    let (mut t0, mut t1) = (0f64, 1f64);
    for i in 0..7 {
        if da[i] < 0.0 && db[i] < 0.0 {
            return None;
        }
        if da[i] < 0.0 {
            t0 = t0.max(da[i] / (da[i] - db[i]));
        } else if db[i] < 0.0 {
            t1 = t1.min(da[i] / (da[i] - db[i]));
        }
    }
    (t0 <= t1).then(|| (lerp(&a, &b, t0), lerp(&a, &b, t1)))
}

fn triangle(state: &RenderState, v: [Vtx; 3], flat_color: DVec4, target: &mut Target) {
    let vp = state.viewport;
    let [n, f] = state.depth_range.map(f64::from);
    let win: Vec<(f64, f64, f64, f64)> = v
        .iter()
        .map(|v| {
            let ndc = v.pos / v.pos.w;
            (
                (ndc.x + 1.0) * vp.width as f64 / 2.0 + vp.x as f64,
                (ndc.y + 1.0) * vp.height as f64 / 2.0 + vp.y as f64,
                ndc.z * (f - n) / 2.0 + (f + n) / 2.0,
                1.0 / v.pos.w,
            )
        })
        .collect();
    let edge = |a: usize, b: usize, x: f64, y: f64| {
        (win[b].0 - win[a].0) * (y - win[a].1) - (win[b].1 - win[a].1) * (x - win[a].0)
    };
    let area = edge(0, 1, win[2].0, win[2].1);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let front = (area > 0.0) == (state.front_face == Winding::Ccw);
    match state.cull {
        Some(CullFace::FrontAndBack) => return,
        Some(CullFace::Front) if front => return,
        Some(CullFace::Back) if !front => return,
        _ => {}
    }
    let sign = area.signum();
    // Top-left ownership of pixels exactly on an edge, for the counter-clockwise orientation.
    let owns = |a: usize, b: usize| {
        let (dx, dy) = ((win[b].0 - win[a].0) * sign, (win[b].1 - win[a].1) * sign);
        dy < 0.0 || (dy == 0.0 && dx < 0.0)
    };
    // Only pixels whose centers can lie inside: the rest could not pass the edge tests.
    let (lo_x, hi_x) = win
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), w| (l.min(w.0), h.max(w.0)));
    let (lo_y, hi_y) = win
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), w| (l.min(w.1), h.max(w.1)));
    let to_px = |v: f64| v.clamp(i32::MIN as f64, i32::MAX as f64) as i32;
    let bounds = state
        .pixel_bounds(target.bounds())
        .intersect(super::target::Rect {
            x0: to_px((lo_x - 0.5).floor()),
            y0: to_px((lo_y - 0.5).floor()),
            x1: to_px((hi_x + 0.5).ceil()),
            y1: to_px((hi_y + 0.5).ceil()),
        });
    let width = target.width() as usize;
    let format = target.format();
    // Polygon offset from the exact window-space depth slopes of the unsnapped triangle.
    let offset = match (state.polygon_offset, format.depth) {
        (Some(o), Some(df)) => {
            let dzdx = ((win[1].2 - win[0].2) * (win[2].1 - win[0].1)
                - (win[2].2 - win[0].2) * (win[1].1 - win[0].1))
                / area;
            let dzdy = ((win[2].2 - win[0].2) * (win[1].0 - win[0].0)
                - (win[1].2 - win[0].2) * (win[2].0 - win[0].0))
                / area;
            o.offset(dzdx.abs().max(dzdy.abs()), df.max() as f64)
        }
        _ => 0.0,
    };
    let textured = state.textures.iter().any(Option::is_some) || state.fog.is_some();
    let (colors, depths, stencils) = target.buffers_mut();
    for y in bounds.y0..bounds.y1 {
        for x in bounds.x0..bounds.x1 {
            let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
            let e = [
                edge(1, 2, px, py) * sign,
                edge(2, 0, px, py) * sign,
                edge(0, 1, px, py) * sign,
            ];
            let pairs = [(1, 2), (2, 0), (0, 1)];
            let inside =
                (0..3).all(|i| e[i] > 0.0 || (e[i] == 0.0 && owns(pairs[i].0, pairs[i].1)));
            if !inside {
                continue;
            }
            let b = e.map(|v| v / (area * sign));
            let at = y as usize * width + x as usize;
            let z = b[0] * win[0].2 + b[1] * win[1].2 + b[2] * win[2].2 + offset;
            let color = if state.shade_model == ShadeModel::Flat {
                flat_color
            } else {
                let q = b[0] * win[0].3 + b[1] * win[1].3 + b[2] * win[2].3;
                (v[0].color * (b[0] * win[0].3)
                    + v[1].color * (b[1] * win[1].3)
                    + v[2].color * (b[2] * win[2].3))
                    / q
            };
            let color = if textured {
                // Perspective-correct interpolation at (x, y) of value·(1/w), divided by the
                // interpolated 1/w; exact derivatives of s/q from the linear numerator and
                // denominator at the neighbouring centers.
                let bary = |px: f64, py: f64| {
                    [
                        edge(1, 2, px, py) / area,
                        edge(2, 0, px, py) / area,
                        edge(0, 1, px, py) / area,
                    ]
                };
                let lin = |b: &[f64; 3], f: &dyn Fn(usize) -> f64| {
                    (0..3).map(|i| b[i] * win[i].3 * f(i)).sum::<f64>()
                };
                let (b0, bx, by) = (bary(px, py), bary(px + 1.0, py), bary(px, py + 1.0));
                let coords: Vec<Option<texturing::Coords>> = (0..TEXTURE_UNITS)
                    .map(|u| {
                        let unit = state.textures[u].as_ref()?;
                        if unit.sampler.cube.is_some() {
                            // The direction's components, each times 1/w (q is ignored).
                            let dir = |b: &[f64; 3]| {
                                [
                                    lin(b, &|i| v[i].tex[u].x),
                                    lin(b, &|i| v[i].tex[u].y),
                                    lin(b, &|i| v[i].tex[u].z),
                                ]
                            };
                            return Some(texturing::cube_coords(dir(&b0), dir(&bx), dir(&by)));
                        }
                        let ratio = |b: &[f64; 3]| {
                            let q = lin(b, &|i| v[i].tex[u].w);
                            (
                                lin(b, &|i| v[i].tex[u].x) / q,
                                lin(b, &|i| v[i].tex[u].y) / q,
                            )
                        };
                        let (s, t) = ratio(&b0);
                        // The ratio's derivative: N/D with N, D linear, exactly.
                        let d = |bb: &[f64; 3]| {
                            let (q0, q1) =
                                (lin(&b0, &|i| v[i].tex[u].w), lin(bb, &|i| v[i].tex[u].w));
                            let (n0, n1) =
                                (lin(&b0, &|i| v[i].tex[u].x), lin(bb, &|i| v[i].tex[u].x));
                            let (m0, m1) =
                                (lin(&b0, &|i| v[i].tex[u].y), lin(bb, &|i| v[i].tex[u].y));
                            let (dq, dn, dm) = (q1 - q0, n1 - n0, m1 - m0);
                            (
                                (dn * q0 - n0 * dq) / (q0 * q0),
                                (dm * q0 - m0 * dq) / (q0 * q0),
                            )
                        };
                        let (ds_dx, dt_dx) = d(&bx);
                        let (ds_dy, dt_dy) = d(&by);
                        Some(texturing::Coords {
                            s,
                            t,
                            ds_dx,
                            dt_dx,
                            ds_dy,
                            dt_dy,
                            face: None,
                        })
                    })
                    .collect();
                let iw = lin(&b0, &|_| 1.0);
                let z_eye = lin(&b0, &|i| v[i].eye_z.abs()) / iw;
                texturing::shade(state, color, &coords, z_eye)
            } else {
                color
            };
            let pixel = fragment::Pixel {
                color: &mut colors[at],
                depth: depths.get_mut(at),
                stencil: stencils.get_mut(at),
            };
            fragment::process(state, format, x, y, color, z, pixel);
        }
    }
}
