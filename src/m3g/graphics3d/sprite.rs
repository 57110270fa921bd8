//! Sprites: a Sprite3D's screen rectangle, and the sprite drawn through the core as flat
//! quads, one per image texel of the crop rectangle, with fog computed here at the sprite's
//! depth.

use glam::{Mat4, Vec4};

use crate::core::{
    self, AttribArray, AttribSource, DrawCall, Indices, Primitive, RenderState, ShadeModel,
};

use super::Bound;
use crate::m3g::appearance::{apply_compositing, core_fog, Appearance};
use crate::m3g::mesh::Sprite3D;

/// A sprite's draw call: triangles with a color per vertex and nothing else (submeshes
/// build theirs in `draw::draw_submesh`).
fn draw_call<'a>(
    indices: Indices<'a>,
    position: AttribArray<'a>,
    color: AttribSource<'a>,
) -> DrawCall<'a> {
    let mut call = DrawCall::new(Primitive::Triangles, indices, position);
    call.color = color;
    call
}

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
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

/// Draws a sprite as one flat quad per crop pixel, in NDC, through the core (so blending,
/// alpha and depth tests are the core's).
pub(super) fn draw_sprite(
    base: &RenderState,
    b: &mut Bound,
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
    let mut s = base.clone();
    s.modelview = Mat4::IDENTITY;
    s.projection = Mat4::IDENTITY;
    s.shade_model = ShadeModel::Flat;
    s.cull = None;
    let a = app.d().clone();
    apply_compositing(&mut s, a.compositing_mode.as_ref(), b.depth);
    // Fog at the sprite's depth, by the core's fog equation.
    let fog = a.fog.as_ref().map(|f| {
        let fog = core_fog(&f.d());
        (fog.factor(dist.abs()), fog)
    });
    let img = sprite.image();
    let id = img.d();
    let (ncols, nrows) = (cw.unsigned_abs() as usize, ch.unsigned_abs() as usize);
    let (vx, vy, vw, vh) = (
        viewport[0] as f32,
        viewport[1] as f32,
        viewport[2] as f32,
        viewport[3] as f32,
    );
    let ndc_x = |x: f32| (x - vx) / vw * 2.0 - 1.0;
    let ndc_y = |y: f32| 1.0 - (y - vy) / vh * 2.0;
    let mut pos = Vec::new();
    let mut col = Vec::new();
    for j in 0..nrows {
        let iy = crop_y
            + if ch > 0 {
                j as i32
            } else {
                (nrows - 1 - j) as i32
            };
        if !(0..id.height).contains(&iy) {
            continue;
        }
        for i in 0..ncols {
            let ix = crop_x
                + if cw > 0 {
                    i as i32
                } else {
                    (ncols - 1 - i) as i32
                };
            if !(0..id.width).contains(&ix) {
                continue;
            }
            let mut c = Vec4::from_array(id.rgba(ix, iy));
            c.w *= alpha;
            if let Some((f, fog)) = &fog {
                let mut rgba = c.to_array();
                fog.apply(*f, &mut rgba);
                c = Vec4::from_array(rgba);
            }
            let (xa, xb) = (
                x0 + w * i as f32 / ncols as f32,
                x0 + w * (i + 1) as f32 / ncols as f32,
            );
            let (ya, yb) = (
                y0 + h * j as f32 / nrows as f32,
                y0 + h * (j + 1) as f32 / nrows as f32,
            );
            let (l, r, t, bt) = (ndc_x(xa), ndc_x(xb), ndc_y(ya), ndc_y(yb));
            for (px, py) in [(l, bt), (r, bt), (r, t), (l, bt), (r, t), (l, t)] {
                pos.extend([px, py, z]);
                col.extend(c.to_array());
            }
        }
    }
    if pos.is_empty() {
        return;
    }
    let (pb, cb) = (f32_bytes(&pos), f32_bytes(&col));
    let call = draw_call(
        Indices::Range {
            first: 0,
            count: pos.len() / 3,
        },
        AttribArray {
            data: &pb,
            ty: core::ComponentType::Float,
            size: 3,
            stride: 12,
            normalized: false,
        },
        AttribSource::Array(AttribArray {
            data: &cb,
            ty: core::ComponentType::Float,
            size: 4,
            stride: 16,
            normalized: false,
        }),
    );
    let _ = core::record_into(&s, &call, &mut b.frame, &mut b.target);
}
