//! Sprites: a Sprite3D's screen rectangle (M3G §2.9), and the sprite drawn through the core
//! as one textured quad: the image is a nearest-sampled texture, MODULATE with the color
//! (1, 1, 1, alpha factor) applies the node alpha, and the core's fog stage fogs it at the
//! sprite's eye depth.

use glam::{Mat4, Vec4};

use gles_cm_core::texenv::{TexEnv, TextureUnit};
use gles_cm_core::texture::{MagFilter, MinFilter, Wrap};
use gles_cm_core::{
    AttribArray, AttribSource, ComponentType, Destination, DrawCall, Indices, Primitive,
    RenderState, ShadeModel,
};

use super::draw::TexCache;
use super::{Bound, RenderStats};
use crate::appearance::{apply_compositing, core_fog, Appearance};
use crate::mesh::Sprite3D;

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

/// A tightly packed array of `size` floats per vertex.
fn floats(data: &[u8], size: usize) -> AttribArray<'_> {
    AttribArray {
        data,
        ty: ComponentType::Float,
        size,
        stride: 4 * size,
        normalized: false,
    }
}

/// A sprite's screen rectangle (M3G window coordinates: x right, y down), depth in NDC, and
/// eye distance; `None` when culled.
pub(crate) fn sprite_rect(
    sprite: &Sprite3D,
    modelview: Mat4,
    projection: Mat4,
    viewport: [i32; 4],
) -> Option<([f32; 4], f32, f32)> {
    let d = sprite.d();
    let [vx, vy, vw, vh] = viewport.map(|v| v as f32);
    let o = modelview * Vec4::new(0.0, 0.0, 0.0, 1.0);
    let oc = projection * o;
    if oc.w <= 0.0 {
        return None;
    }
    let on = oc.truncate() / oc.w;
    if !(-1.0..=1.0).contains(&on.z) {
        return None;
    }
    let (w, h) = if d.scaled {
        let x = modelview * Vec4::new(1.0, 0.0, 0.0, 1.0);
        let y = modelview * Vec4::new(0.0, 1.0, 0.0, 1.0);
        let o3 = o.truncate() / o.w;
        let dx = (x.truncate() / x.w - o3).length();
        let dy = (y.truncate() / y.w - o3).length();
        let xc = projection * (o + Vec4::new(dx, 0.0, 0.0, 0.0));
        let yc = projection * (o + Vec4::new(0.0, dy, 0.0, 0.0));
        let sx = (xc.truncate() / xc.w - on).truncate().length();
        let sy = (yc.truncate() / yc.w - on).truncate().length();
        (0.5 * sx * vw, 0.5 * sy * vh)
    } else {
        (d.crop[2].abs() as f32, d.crop[3].abs() as f32)
    };
    let cx = vx + (on.x + 1.0) * 0.5 * vw;
    let cy = vy + (1.0 - on.y) * 0.5 * vh;
    let (mut x0, mut y0) = (cx - w * 0.5, cy - h * 0.5);
    if !d.scaled {
        x0 = x0.round();
        y0 = y0.round();
    }
    Some(([x0, y0, w, h], on.z, -o.z / o.w))
}

/// The part of one crop axis that lies in the image: `(a, b, ta, tb)`, where cells `a .. b`
/// of the sprite's `|len|` cells (in screen order: left to right, top to bottom) show
/// image texels, and `ta`, `tb` are the texture coordinates at the edges of cells `a` and
/// `b`. A negative `len` mirrors the axis. Crop texels outside the image act as alpha-test
/// failures (M3G §2.9), so the quad simply leaves them out; `None` when none is inside.
fn visible_cells(start: i32, len: i32, size: i32) -> Option<(i64, i64, f32, f32)> {
    let (start, n, size) = (i64::from(start), i64::from(len).abs(), i64::from(size));
    let (lo, hi) = (start.max(0), (start + n).min(size));
    if lo >= hi {
        return None;
    }
    let tc = |t: i64| t as f32 / size as f32;
    Some(if len > 0 {
        (lo - start, hi - start, tc(lo), tc(hi))
    } else {
        (n - (hi - start), n - (lo - start), tc(hi), tc(lo))
    })
}

/// Draws a sprite through the core (so blending, the alpha and depth tests, texturing and
/// fog are the core's) as two triangles in NDC with the image as texture 0.
#[allow(clippy::too_many_arguments)]
pub(super) fn draw_sprite(
    base: &RenderState,
    b: &mut Bound,
    textures: &mut TexCache,
    stats: &mut RenderStats,
    sprite: &Sprite3D,
    app: &Appearance,
    mv: Mat4,
    alpha: f32,
) {
    let [crop_x, crop_y, cw, ch] = sprite.d().crop;
    if cw == 0 || ch == 0 {
        return;
    }
    let vp = base.viewport;
    let th = b.target.height() as i32;
    let viewport = [vp.x, th - vp.y - vp.height, vp.width, vp.height];
    let Some(([x0, y0, w, h], z, dist)) = sprite_rect(sprite, mv, base.projection, viewport) else {
        return;
    };
    let image = sprite.image();
    let (iw, ih) = {
        let d = image.d();
        (d.width, d.height)
    };
    let (Some((ca, cb, sa, sb)), Some((ra, rb, ta, tb))) =
        (visible_cells(crop_x, cw, iw), visible_cells(crop_y, ch, ih))
    else {
        return;
    };
    let a = app.d().clone();
    let mut s = base.clone();
    s.shade_model = ShadeModel::Flat;
    s.cull = None;
    apply_compositing(&mut s, a.compositing_mode.as_ref(), b.depth);
    // Positions arrive in NDC with their eye depth as z: the modelview is the identity (so
    // fog reads the eye distance) and the projection keeps x and y and puts the sprite's
    // NDC depth into z.
    s.modelview = Mat4::IDENTITY;
    s.projection = Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::ZERO, Vec4::new(0.0, 0.0, z, 1.0));
    s.fog = a.fog.as_ref().map(|f| core_fog(&f.d()));
    let eye_z = if s.fog.is_some() { -dist } else { 0.0 };
    let key = (
        MinFilter::Nearest,
        MagFilter::Nearest,
        Wrap::ClampToEdge,
        Wrap::ClampToEdge,
    );
    s.textures[0] = Some(TextureUnit {
        sampler: textures.image_sampler(&image, key, stats),
        env: TexEnv::default(),
        coord_replace: false,
    });

    let [vx, vy, vw, vh] = viewport.map(|v| v as f32);
    let ndc_x = |x: f32| (x - vx) / vw * 2.0 - 1.0;
    let ndc_y = |y: f32| 1.0 - (y - vy) / vh * 2.0;
    let (nc, nr) = (cw.unsigned_abs() as f32, ch.unsigned_abs() as f32);
    let (l, r) = (
        ndc_x(x0 + w * ca as f32 / nc),
        ndc_x(x0 + w * cb as f32 / nc),
    );
    let (t, bt) = (
        ndc_y(y0 + h * ra as f32 / nr),
        ndc_y(y0 + h * rb as f32 / nr),
    );
    let corners = [
        (l, bt, sa, tb),
        (r, bt, sb, tb),
        (r, t, sb, ta),
        (l, bt, sa, tb),
        (r, t, sb, ta),
        (l, t, sa, ta),
    ];
    let pos: Vec<f32> = corners.iter().flat_map(|c| [c.0, c.1, eye_z]).collect();
    let tex: Vec<f32> = corners.iter().flat_map(|c| [c.2, c.3]).collect();
    let (pb, tb) = (f32_bytes(&pos), f32_bytes(&tex));
    let mut call = DrawCall::new(
        Primitive::Triangles,
        Indices::Range {
            first: 0,
            count: corners.len(),
        },
        floats(&pb, 3),
    );
    call.color = AttribSource::Constant([1.0, 1.0, 1.0, alpha]);
    call.texcoord[0] = AttribSource::Array(floats(&tb, 2));
    // Out of memory drops the draw (M3G has no such exception).
    let _ = gles_cm_core::record_into(&s, &call, &mut b.frame, Destination::Now(&mut b.target));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::appearance::{CompositingMode, Fog};
    use crate::image::Image2D;
    use crate::modes::{Blending, FogMode, ImageFormat, RenderHints};
    use crate::Color;
    use gles_cm_core::target::{ColorFormat, DepthFormat, Target, TargetFormat};
    use gles_cm_core::{Frame, Viewport};

    /// The drawing this module replaced, kept as the reference the quad is held to: one
    /// flat quad per crop texel, colored on the CPU (the image color, alpha times the alpha
    /// factor, then fog at the sprite's depth), in NDC through the core.
    fn per_texel(
        base: &RenderState,
        b: &mut Bound,
        sprite: &Sprite3D,
        app: &Appearance,
        mv: Mat4,
        alpha: f32,
    ) {
        let [crop_x, crop_y, cw, ch] = sprite.d().crop;
        let vp = base.viewport;
        let th = b.target.height() as i32;
        let viewport = [vp.x, th - vp.y - vp.height, vp.width, vp.height];
        let Some(([x0, y0, w, h], z, dist)) = sprite_rect(sprite, mv, base.projection, viewport)
        else {
            return;
        };
        let mut s = base.clone();
        s.modelview = Mat4::IDENTITY;
        s.projection = Mat4::IDENTITY;
        s.shade_model = ShadeModel::Flat;
        s.cull = None;
        let a = app.d().clone();
        apply_compositing(&mut s, a.compositing_mode.as_ref(), b.depth);
        let fog = a.fog.as_ref().map(|f| {
            let fog = core_fog(&f.d());
            (fog.factor(dist.abs()), fog)
        });
        let img = sprite.image();
        let id = img.d();
        let (ncols, nrows) = (cw.unsigned_abs() as usize, ch.unsigned_abs() as usize);
        let [vx, vy, vw, vh] = viewport.map(|v| v as f32);
        let ndc_x = |x: f32| (x - vx) / vw * 2.0 - 1.0;
        let ndc_y = |y: f32| 1.0 - (y - vy) / vh * 2.0;
        let (mut pos, mut col) = (Vec::new(), Vec::new());
        for j in 0..nrows {
            let iy = crop_y + if ch > 0 { j } else { nrows - 1 - j } as i32;
            if !(0..id.height).contains(&iy) {
                continue;
            }
            for i in 0..ncols {
                let ix = crop_x + if cw > 0 { i } else { ncols - 1 - i } as i32;
                if !(0..id.width).contains(&ix) {
                    continue;
                }
                let mut c = id.rgba(ix, iy);
                c[3] *= alpha;
                if let Some((f, fog)) = &fog {
                    fog.apply(*f, &mut c);
                }
                let xa = x0 + w * i as f32 / ncols as f32;
                let xb = x0 + w * (i + 1) as f32 / ncols as f32;
                let ya = y0 + h * j as f32 / nrows as f32;
                let yb = y0 + h * (j + 1) as f32 / nrows as f32;
                let (l, r, t, bt) = (ndc_x(xa), ndc_x(xb), ndc_y(ya), ndc_y(yb));
                for (px, py) in [(l, bt), (r, bt), (r, t), (l, bt), (r, t), (l, t)] {
                    pos.extend([px, py, z]);
                    col.extend(c);
                }
            }
        }
        if pos.is_empty() {
            return;
        }
        let (pb, cb) = (f32_bytes(&pos), f32_bytes(&col));
        let count = pos.len() / 3;
        let mut call = DrawCall::new(
            Primitive::Triangles,
            Indices::Range { first: 0, count },
            floats(&pb, 3),
        );
        call.color = AttribSource::Array(floats(&cb, 4));
        let _ = gles_cm_core::record_into(&s, &call, &mut b.frame, Destination::Now(&mut b.target));
    }

    fn bound(format: ColorFormat, dither: bool) -> Bound {
        let tf = TargetFormat {
            color: format,
            depth: Some(DepthFormat::D16),
            stencil_bits: 0,
        };
        let mut target = Target::new(64, 48, tf);
        target.clear_color(target.bounds(), [0.2, 0.3, 0.4, 0.5], [true; 4]);
        Bound {
            frame: Frame::for_target(&target),
            target,
            image: None,
            format: ImageFormat::Rgb,
            depth: true,
            hints: if dither {
                RenderHints::DITHER
            } else {
                RenderHints::empty()
            },
        }
    }

    fn base(b: &Bound) -> RenderState {
        let mut s = RenderState::new(64, 48);
        s.projection = Mat4::perspective_rh_gl(1.0, 64.0 / 48.0, 0.5, 50.0);
        s.viewport = Viewport {
            x: 3,
            y: 2,
            width: 58,
            height: 44,
        };
        s.dither = !b.hints.is_empty();
        s
    }

    /// The image's pixels: every texel different, alpha varying.
    fn image(format: ImageFormat, w: i32, h: i32) -> Image2D {
        let bpp = format.bytes_per_pixel() as i32;
        let pixels: Vec<u8> = (0..w * h * bpp).map(|i| (i * 37 % 251) as u8).collect();
        Image2D::with_pixels(format, w, h, &pixels).unwrap()
    }

    /// Whether `v` lies within `eps` of one of the `n` + 1 cell edges of `[x0, x0 + w]`.
    fn near_edge(v: f32, x0: f32, w: f32, n: i32, eps: f32) -> bool {
        (0..=n).any(|i| (v - (x0 + w * i as f32 / n as f32)).abs() <= eps)
    }

    /// The quad matches the per-texel drawing: bit for bit for unscaled sprites, whose
    /// cell edges fall on pixel edges; for scaled sprites, except where a pixel center
    /// lies within 1/128 pixel of a cell edge. There the old drawing decided coverage
    /// with cell edges snapped to the 1/256-pixel grid, and the quad samples the texel
    /// under the exact center: either texel is a correct nearest sample.
    #[test]
    fn one_quad_matches_the_per_texel_drawing() {
        let fog_linear = Fog::new();
        fog_linear.set_mode(FogMode::Linear);
        fog_linear.set_linear(1.0, 9.0);
        fog_linear.set_color(Color(0x00_30_80_F0));
        let fog_exp = Fog::new();
        fog_exp.set_mode(FogMode::Exponential);
        fog_exp.set_density(0.15).unwrap();
        fog_exp.set_color(Color(0x00_FF_40_10));
        let blend = CompositingMode::new();
        blend.set_blending(Blending::Alpha);
        blend.set_alpha_threshold(0.25).unwrap();
        let crops = [
            (0, 0, 7, 5),
            (2, 1, -5, 4),
            (-3, -2, 9, 6),
            (4, 3, 6, -7),
            (10, 0, 3, 3),
        ];
        let mut compared = 0;
        for format in [ColorFormat::Rgba8888, ColorFormat::Rgb565] {
            for dither in [false, true] {
                for img_format in [
                    ImageFormat::Rgba,
                    ImageFormat::Rgb,
                    ImageFormat::Alpha,
                    ImageFormat::LuminanceAlpha,
                ] {
                    for (k, &(cx, cy, cw, ch)) in crops.iter().enumerate() {
                        for scaled in [false, true] {
                            let img = image(img_format, 7, 5);
                            let app = Appearance::new();
                            app.set_fog([None, Some(&fog_linear), Some(&fog_exp)][k % 3]);
                            if k % 2 == 1 {
                                app.set_compositing_mode(Some(&blend));
                            }
                            let sprite = Sprite3D::new(scaled, &img, Some(&app));
                            sprite.set_crop(cx, cy, cw, ch).unwrap();
                            let mv = Mat4::from_translation(glam::Vec3::new(
                                0.3 * k as f32 - 0.6,
                                -0.2,
                                -3.0 - k as f32,
                            )) * Mat4::from_scale(glam::Vec3::new(1.3, 0.9, 1.0));
                            let alpha = [1.0, 0.6, 0.35][k % 3];
                            let (mut ours, mut old) =
                                (bound(format, dither), bound(format, dither));
                            let s = base(&ours);
                            let (mut cache, mut stats) =
                                (TexCache::default(), RenderStats::default());
                            draw_sprite(
                                &s, &mut ours, &mut cache, &mut stats, &sprite, &app, mv, alpha,
                            );
                            per_texel(&s, &mut old, &sprite, &app, mv, alpha);
                            ours.frame.flush_into(&mut ours.target);
                            old.frame.flush_into(&mut old.target);
                            let vp = [3, 48 - 2 - 44, 58, 44];
                            let ([x0, y0, w, h], _, _) =
                                sprite_rect(&sprite, mv, s.projection, vp).unwrap();
                            let (n, m) = (cw.abs(), ch.abs());
                            let clear = bound(format, dither).target.color().to_vec();
                            let mut drawn = 0;
                            for (i, ((a, b), c)) in ours
                                .target
                                .color()
                                .iter()
                                .zip(old.target.color())
                                .zip(&clear)
                                .enumerate()
                            {
                                // The pixel center in M3G window coordinates (y down; the
                                // target's rows run bottom up).
                                let (x, y) =
                                    ((i % 64) as f32 + 0.5, 48.0 - ((i / 64) as f32 + 0.5));
                                let edge = scaled
                                    && (near_edge(x, x0, w, n, 1.0 / 128.0)
                                        || near_edge(y, y0, h, m, 1.0 / 128.0));
                                assert!(a == b || edge, "{format:?} dither {dither} image {img_format:?} crop {k} scaled {scaled}: pixel {i}: {a:#x} vs {b:#x}");
                                drawn += usize::from(a != c);
                            }
                            assert!(drawn > 0 || k == 4, "crop {k} draws something");
                            compared += 1;
                        }
                    }
                }
            }
        }
        assert_eq!(compared, 2 * 2 * 4 * 5 * 2);
    }
}
