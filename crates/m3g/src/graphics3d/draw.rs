//! Drawing what [`super::collect`] found: layer by layer, opaque before blended, culled
//! against the frustum; a submesh's Appearance becomes a `RenderState` (through the
//! translations in `appearance.rs`), its VertexBuffer a `DrawCall`, recorded into the bound
//! frame. Also the core textures made from Texture2D images, kept across render calls.

use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

use glam::{Mat4, Vec3, Vec4};

use gles_cm_core::state::{Light as CoreLight, Lighting};
use gles_cm_core::texenv::TextureUnit;
use gles_cm_core::texture::{BaseFormat, Image as TexImage, MagFilter, MinFilter, Sampler, Wrap};
use gles_cm_core::{
    AttribArray, AttribSource, Destination, DrawCall, Indices, Primitive, RenderState, Viewport,
};

use super::collect::{outside_frustum, Item, What};
use super::sprite::draw_sprite;
use super::{Bound, Graphics3D, RenderStats, MAX_LIGHTS};
use crate::appearance::{
    apply_compositing, apply_polygon_mode, argb_to_rgba, core_fog, core_material, rgba_of, tex_env,
    Appearance, TextureData,
};
use crate::error::{ise, Result};
use crate::image::{Image2D, ImageData};
use crate::modes::{ImageFormat, LightMode, RenderHints, TextureFilter, TextureWrap};
use crate::node::node_data;
use crate::object::{tf, Handle};
use crate::transform::invert;
use crate::vertex::{IndexBuffer, VertexBuffer};

/// A light as the core takes it (eye coordinates, intensity folded into the colors) with
/// the scope of its node.
#[derive(Clone, Copy, Debug)]
struct EyeLight {
    light: CoreLight,
    scope: i32,
}

impl Graphics3D {
    /// Draws `items` with the current camera and lights into the bound target, flushing
    /// whenever the frame fills.
    pub(super) fn draw_items(&mut self, mut items: Vec<Item>) -> Result<()> {
        let Some((camera, cam_to_world)) = self.camera.clone() else {
            return ise("no camera");
        };
        let Some(projection) = camera.projection_matrix() else {
            return Ok(());
        };
        let view = invert(&cam_to_world)?;
        let lights = self.eye_lights(&view);
        items.sort_by_key(|i| (i.layer, i.blended));
        let base = self.base_state(projection);
        let Graphics3D {
            bound,
            culling,
            clamp_after_lighting,
            stats,
            textures,
            ..
        } = self;
        let b = bound.as_mut().unwrap();
        textures.calls += 1;
        for item in &items {
            let mut s = base.clone();
            let modelview = view * item.model;
            match &item.what {
                What::Submesh(vb, ib, app) => {
                    if *culling && item.cullable && outside_frustum(&vb.d(), modelview, projection)
                    {
                        stats.submeshes_culled += 1;
                        continue;
                    }
                    s.modelview = modelview;
                    let lit = LitBy {
                        lights: &lights,
                        clamp_after_lighting: *clamp_after_lighting,
                    };
                    draw_submesh(&mut s, b, textures, stats, vb, ib, app, item, lit);
                }
                What::Sprite(sprite, app) => {
                    draw_sprite(&s, b, textures, stats, sprite, app, modelview, item.alpha);
                }
            }
            b.frame.flush_if_full(&mut b.target);
        }
        // Textures unused for a while are dropped.
        let calls = textures.calls;
        textures
            .entries
            .retain(|_, e| calls.saturating_sub(e.used) < 16);
        Ok(())
    }

    /// The enabled lights of the light array in eye coordinates, as core lights (M3G §2.6:
    /// the intensity scales the colors; AMBIENT has only an ambient color, the others only
    /// diffuse and specular; directional lights shine along their local −Z).
    fn eye_lights(&self, view: &Mat4) -> Vec<EyeLight> {
        let mut out = Vec::new();
        for (light, m) in self.lights.iter().flatten() {
            let nd = node_data(&light.0);
            if !nd.rendering {
                continue;
            }
            let d = light.d();
            let mv = *view * *m;
            let [r, g, b, _] = argb_to_rgba(d.color);
            let color = (Vec3::new(r, g, b) * d.intensity).extend(1.0);
            let black = Vec4::new(0.0, 0.0, 0.0, 1.0);
            let mut l = CoreLight {
                ambient: black,
                diffuse: color,
                specular: color,
                ..CoreLight::default()
            };
            match d.mode {
                LightMode::Ambient => {
                    l.ambient = color;
                    l.diffuse = black;
                    l.specular = black;
                }
                LightMode::Directional => l.position = mv * Vec4::Z,
                _ => {
                    l.position = mv * Vec4::W;
                    l.attenuation = d.attenuation;
                    if d.mode == LightMode::Spot {
                        l.spot_direction = (mv * Vec4::NEG_Z).truncate();
                        l.spot_cutoff = d.spot_angle;
                        l.spot_exponent = d.spot_exponent;
                    }
                }
            }
            out.push(EyeLight {
                light: l,
                scope: nd.scope,
            });
        }
        out
    }

    fn base_state(&self, projection: Mat4) -> RenderState {
        let b = self.bound.as_ref().unwrap();
        let (tw, th) = (b.target.width() as i32, b.target.height() as i32);
        let [x, y, w, h] = self.viewport;
        let mut s = RenderState::new(tw, th);
        s.projection = projection;
        s.viewport = Viewport {
            x,
            y: th - y - h,
            width: w,
            height: h,
        };
        s.scissor = Some(self.clear_rect());
        s.depth_range = self.depth_range;
        s.dither = b.hints.contains(RenderHints::DITHER);
        s
    }
}

/// A texture image converted for the core, with what it was made from.
struct TexEntry {
    /// Keeps the image alive, so its address (the key) is not reused.
    _image: Image2D,
    /// The pixels converted, for a mutable image (whose contents may change in place).
    pixels: Option<Vec<u8>>,
    sampler: Arc<Sampler>,
    /// The render call that last used it.
    used: u64,
}

type TexKey = (usize, MinFilter, MagFilter, Wrap, Wrap);

/// The core textures of the Texture2D images in use, kept across render calls.
#[derive(Default)]
pub(super) struct TexCache {
    entries: HashMap<TexKey, TexEntry>,
    /// Render calls so far.
    calls: u64,
}

/// M3G's level filter × image filter → the core's minification filter (checklist §2.1).
fn min_filter(level: TextureFilter, image: TextureFilter) -> MinFilter {
    let linear = image == TextureFilter::Linear;
    match (level, linear) {
        (TextureFilter::Nearest, false) => MinFilter::NearestMipmapNearest,
        (TextureFilter::Nearest, true) => MinFilter::LinearMipmapNearest,
        (TextureFilter::Linear, false) => MinFilter::NearestMipmapLinear,
        (TextureFilter::Linear, true) => MinFilter::LinearMipmapLinear,
        (TextureFilter::BaseLevel, false) => MinFilter::Nearest,
        (TextureFilter::BaseLevel, true) => MinFilter::Linear,
    }
}

/// An Image2D as a core texture: its format mapped to the core's base format (texels
/// expanded as `gles_cm_core::texture` stores them), row 0 (the top row) at t = 0, and the mipmap
/// chain (2 × 2 box filter) when `min` uses one.
fn build_sampler(d: &ImageData, min: MinFilter, mag: MagFilter, ws: Wrap, wt: Wrap) -> Sampler {
    let format = match d.format {
        ImageFormat::Alpha => BaseFormat::Alpha,
        ImageFormat::Luminance => BaseFormat::Luminance,
        ImageFormat::LuminanceAlpha => BaseFormat::LuminanceAlpha,
        ImageFormat::Rgb => BaseFormat::Rgb,
        ImageFormat::Rgba => BaseFormat::Rgba,
    };
    let bpp = format.components();
    let texels = d
        .pixels
        .chunks_exact(bpp)
        .map(|p| {
            u32::from_le_bytes(match format {
                BaseFormat::Alpha => [0, 0, 0, p[0]],
                BaseFormat::Luminance => [p[0], p[0], p[0], 255],
                BaseFormat::LuminanceAlpha => [p[0], p[0], p[0], p[1]],
                BaseFormat::Rgb => [p[0], p[1], p[2], 255],
                BaseFormat::Rgba => [p[0], p[1], p[2], p[3]],
            })
        })
        .collect();
    let mut levels = vec![Arc::new(TexImage {
        width: d.width as u32,
        height: d.height as u32,
        format,
        texels,
    })];
    if min.uses_mipmaps() {
        loop {
            let last = levels.last().unwrap();
            if last.width == 1 && last.height == 1 {
                break;
            }
            let next = last.half();
            levels.push(Arc::new(next));
        }
    }
    Sampler::new(levels, min, mag, ws, wt)
}

impl TexCache {
    /// The core texture of `t`, converted again only when needed.
    fn sampler(&mut self, t: &TextureData, stats: &mut RenderStats) -> Arc<Sampler> {
        let wrap = |w| match w {
            TextureWrap::Clamp => Wrap::ClampToEdge,
            TextureWrap::Repeat => Wrap::Repeat,
        };
        let min = min_filter(t.level_filter, t.image_filter);
        let mag = if t.image_filter == TextureFilter::Linear {
            MagFilter::Linear
        } else {
            MagFilter::Nearest
        };
        let key = (min, mag, wrap(t.wrap[0]), wrap(t.wrap[1]));
        self.image_sampler(&t.image, key, stats)
    }

    /// The core texture of `image` sampled as `(min, mag, wrap s, wrap t)` says (a sprite's
    /// image, or a Texture2D's).
    pub(super) fn image_sampler(
        &mut self,
        image: &Image2D,
        (min, mag, ws, wt): (MinFilter, MagFilter, Wrap, Wrap),
        stats: &mut RenderStats,
    ) -> Arc<Sampler> {
        let key = (Rc::as_ptr(&image.0) as usize, min, mag, ws, wt);
        let d = image.d();
        if let Some(e) = self.entries.get_mut(&key) {
            if e.pixels.as_ref().is_none_or(|p| *p == d.pixels) {
                e.used = self.calls;
                return e.sampler.clone();
            }
        }
        stats.texture_uploads += 1;
        let sampler = Arc::new(build_sampler(&d, min, mag, ws, wt));
        self.entries.insert(
            key,
            TexEntry {
                _image: image.clone(),
                pixels: d.mutable.then(|| d.pixels.clone()),
                sampler: sampler.clone(),
                used: self.calls,
            },
        );
        sampler
    }
}

/// The scene's lights in eye space and how their result is clamped.
#[derive(Clone, Copy)]
struct LitBy<'a> {
    lights: &'a [EyeLight],
    clamp_after_lighting: bool,
}

/// Draws one submesh: the Appearance becomes the state (compositing, polygon mode,
/// lighting, fog, texture units), the VertexBuffer the draw call (positions with scale and
/// bias in the modelview, normals, colors, texture coordinates with their scale and bias
/// in the texture matrices), and the core does the rest.
#[allow(clippy::too_many_arguments)]
fn draw_submesh(
    s: &mut RenderState,
    b: &mut Bound,
    textures: &mut TexCache,
    stats: &mut RenderStats,
    vb: &VertexBuffer,
    ib: &IndexBuffer,
    app: &Appearance,
    item: &Item,
    lit: LitBy,
) {
    let a = app.d().clone();
    apply_compositing(s, a.compositing_mode.as_ref(), b.depth);
    apply_polygon_mode(s, a.polygon_mode.as_ref());
    let vbd = vb.d();
    let pos = vbd.positions.clone().expect("validated");
    let pd = pos.d();
    let scale = vbd.pos_scale;
    // Scale and bias fold into the modelview.
    s.modelview = s.modelview
        * Mat4::from_translation(Vec3::from_array(vbd.pos_bias))
        * Mat4::from_scale(Vec3::splat(scale));
    // Lighting (only with a Material): no scene ambient, one material for both faces,
    // vertex color tracking as color material, normals always normalized.
    let material = a.material.as_ref().map(|m| m.d().clone());
    if let Some(m) = &material {
        let two_side = a.polygon_mode.as_ref().is_some_and(|p| p.d().two_sided);
        let mat = core_material(m, item.alpha);
        s.lighting = Some(Lighting {
            lights: lit
                .lights
                .iter()
                .filter(|l| l.scope & item.scope != 0)
                .take(MAX_LIGHTS)
                .map(|l| l.light)
                .collect(),
            model_ambient: Vec4::ZERO,
            two_side,
            front: mat,
            back: mat,
            color_material: m.tracking,
            clamp_after_lighting: lit.clamp_after_lighting,
        });
        s.normalize = true;
    }
    s.fog = a.fog.as_ref().map(|f| core_fog(&f.d()));
    // The alpha factor multiplies the post-lighting alpha: the material's diffuse alpha
    // (folded above), else the vertex color's.
    let alpha_on_vertex = material.as_ref().is_none_or(|m| m.tracking) && item.alpha != 1.0;
    let colors = vbd.colors.clone();
    let cd = colors.as_ref().map(|c| c.d());
    let float_colors: Vec<u8>;
    let color = match &cd {
        Some(cd) if alpha_on_vertex => {
            let comps = cd.comps as usize;
            float_colors = cd
                .data
                .chunks_exact(comps)
                .flat_map(|p| {
                    let a = if comps == 4 { p[3] as f32 / 255.0 } else { 1.0 };
                    [
                        p[0] as f32 / 255.0,
                        p[1] as f32 / 255.0,
                        p[2] as f32 / 255.0,
                        a * item.alpha,
                    ]
                })
                .flat_map(f32::to_ne_bytes)
                .collect();
            AttribSource::Array(AttribArray {
                data: &float_colors,
                ty: gles_cm_core::ComponentType::Float,
                size: 4,
                stride: 16,
                normalized: false,
            })
        }
        Some(cd) => AttribSource::Array(AttribArray {
            data: &cd.data,
            ty: gles_cm_core::ComponentType::UnsignedByte,
            size: cd.comps as usize,
            stride: cd.comps as usize,
            normalized: true,
        }),
        None => {
            let mut c = rgba_of(vbd.default_color);
            if alpha_on_vertex {
                c.w *= item.alpha;
            }
            AttribSource::Constant(c.to_array())
        }
    };
    // Normals carry no scale: a negative position scale (in the modelview) would turn them
    // around, so they are turned back.
    let normals = vbd.normals.clone().filter(|_| s.lighting.is_some());
    let nd = normals.as_ref().map(|n| n.d());
    let flipped: Vec<u8>;
    let normal = match &nd {
        Some(nd) => {
            let arr = AttribArray {
                data: &nd.data,
                ty: component_type(nd.size),
                size: 3,
                stride: 3 * nd.size as usize,
                normalized: true,
            };
            if scale < 0.0 {
                flipped = (0..nd.count as usize)
                    .flat_map(|v| {
                        let n = arr.fetch(v);
                        [-n[0], -n[1], -n[2]]
                    })
                    .flat_map(f32::to_ne_bytes)
                    .collect();
                AttribSource::Array(AttribArray {
                    data: &flipped,
                    ty: gles_cm_core::ComponentType::Float,
                    size: 3,
                    stride: 12,
                    normalized: false,
                })
            } else {
                AttribSource::Array(arr)
            }
        }
        None => AttribSource::Constant([0.0, 0.0, 1.0, 0.0]),
    };
    // Texture units: the Texture2D's image and parameters, its transform T·R·S·M after the
    // coordinates' scale and bias.
    let mut units = Vec::new();
    for (u, t) in a.textures.iter().enumerate() {
        let Some(t) = t else { continue };
        let td = t.d();
        s.textures[u] = Some(TextureUnit {
            sampler: textures.sampler(&td, stats),
            env: tex_env(&td),
            coord_replace: false,
        });
        let tex_m = tf(t.raw()).composite();
        s.texture_matrices[u] = match &vbd.texcoords[u] {
            Some((va, tscale, tbias)) => {
                units.push((u, va.clone()));
                tex_m
                    * Mat4::from_translation(Vec3::from_array(*tbias))
                    * Mat4::from_scale(Vec3::splat(*tscale))
            }
            None => tex_m,
        };
    }
    let tds: Vec<_> = units.iter().map(|(u, va)| (*u, va.d())).collect();
    let ibd = ib.d();
    let indices = Indices::U16(&ibd.triangles);
    let mut call = DrawCall::new(
        Primitive::Triangles,
        indices,
        AttribArray {
            data: &pd.data,
            ty: component_type(pd.size),
            size: 3,
            stride: 3 * pd.size as usize,
            normalized: false,
        },
    );
    call.color = color;
    call.normal = normal;
    for (u, td) in &tds {
        call.texcoord[*u] = AttribSource::Array(AttribArray {
            data: &td.data,
            ty: component_type(td.size),
            size: td.comps as usize,
            stride: (td.comps * td.size) as usize,
            normalized: false,
        });
    }
    stats.submeshes_drawn += 1;
    if let Some((lo, hi)) = indices.range() {
        stats.vertices_transformed += (hi - lo + 1) as u64;
    }
    // Out of memory drops the draw (M3G has no such exception).
    let _ = gles_cm_core::record_into(s, &call, &mut b.frame, Destination::Now(&mut b.target));
}

fn component_type(size: i32) -> gles_cm_core::ComponentType {
    if size == 1 {
        gles_cm_core::ComponentType::Byte
    } else {
        gles_cm_core::ComponentType::Short
    }
}
