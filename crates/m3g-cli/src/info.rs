//! `m3g info`: a loaded file's object graph, as an indented text tree or as JSON.
//!
//! Every object gets its index in the file (2 for the first object after the header, as in
//! the format); objects reached through an external reference to another .m3g file get the
//! numbers after the file's last index and are marked external. Each object lists its class,
//! user ID, key parameters and references; the animation section lists every track with
//! what it animates and when it is over (as `m3g render --animate` computes it).

use std::collections::HashMap;
use std::path::Path;

use m3g::loader::Loaded;
use m3g::*;

use crate::json::Json;
use crate::scene;

/// A parameter value: plain, or a reference to another object (its index).
enum Val {
    J(Json),
    Ref(Option<usize>),
}

macro_rules! val_from {
    ($($t:ty),*) => {
        $(impl From<$t> for Val {
            fn from(v: $t) -> Val {
                Val::J(v.into())
            }
        })*
    };
}
val_from!(
    bool,
    i32,
    i64,
    usize,
    f32,
    &str,
    String,
    Vec<f32>,
    Vec<i32>,
    Vec<usize>,
    Vec<&str>
);

struct Entry {
    obj: Object3D,
    index: usize,
    external: bool,
}

/// The objects of one load, numbered.
pub struct Graph {
    entries: Vec<Entry>,
    #[allow(clippy::mutable_key_type)]
    index: HashMap<Object3D, usize>,
    roots: Vec<usize>,
    /// For each entry, the entries holding it as an animation track.
    track_targets: HashMap<usize, Vec<usize>>,
}

impl Graph {
    #[allow(clippy::mutable_key_type)]
    pub fn new(loaded: &Loaded) -> Graph {
        let mut entries = Vec::new();
        let mut index = HashMap::new();
        for (i, o) in loaded.objects.iter().enumerate() {
            if !index.contains_key(o) {
                index.insert(o.clone(), entries.len());
                entries.push(Entry {
                    obj: o.clone(),
                    index: i + 2,
                    external: false,
                });
            }
        }
        // Objects only reachable through external references.
        let mut next = loaded.objects.len() + 2;
        let mut stack: Vec<Object3D> = loaded.roots.iter().rev().cloned().collect();
        let mut visited = std::collections::HashSet::new();
        while let Some(o) = stack.pop() {
            if !visited.insert(o.clone()) {
                continue;
            }
            if !index.contains_key(&o) {
                index.insert(o.clone(), entries.len());
                entries.push(Entry {
                    obj: o.clone(),
                    index: next,
                    external: true,
                });
                next += 1;
            }
            let mut refs = o.get_references();
            refs.reverse();
            stack.extend(refs);
        }
        let roots = loaded
            .roots
            .iter()
            .filter_map(|r| index.get(r).copied())
            .collect();
        let mut track_targets: HashMap<usize, Vec<usize>> = HashMap::new();
        for (k, e) in entries.iter().enumerate() {
            for i in 0..e.obj.animation_track_count() {
                let track = e.obj.animation_track(i).map(Object3D::from);
                if let Some(t) = track.ok().and_then(|t| index.get(&t)) {
                    track_targets.entry(*t).or_default().push(k);
                }
            }
        }
        Graph {
            entries,
            index,
            roots,
            track_targets,
        }
    }

    fn idx(&self, o: &Object3D) -> Option<usize> {
        self.index.get(o).map(|&k| self.entries[k].index)
    }

    fn r<T: Object3DExt>(&self, o: Option<T>) -> Val {
        Val::Ref(o.and_then(|o| self.idx(&o.as_object3d())))
    }

    fn refs(&self, o: &Object3D) -> Vec<usize> {
        let mut out: Vec<usize> = Vec::new();
        for r in o.get_references() {
            if let Some(i) = self.idx(&r) {
                if !out.contains(&i) {
                    out.push(i);
                }
            }
        }
        out
    }

    /// The key parameters of `o`, by class.
    fn params(&self, o: &Object3D) -> Vec<(&'static str, Val)> {
        let mut p: Vec<(&'static str, Val)> = Vec::new();
        if let Some(n) = o.downcast::<Node>() {
            if !n.is_rendering_enabled() {
                p.push(("rendering", false.into()));
            }
            if n.alpha_factor() != 1.0 {
                p.push(("alpha_factor", n.alpha_factor().into()));
            }
            let t = n.get_translation();
            if t != [0.0; 3] {
                p.push(("translation", t.to_vec().into()));
            }
            let s = n.get_scale();
            if s != [1.0; 3] {
                p.push(("scale", s.to_vec().into()));
            }
            let r = n.get_orientation();
            if r[0] != 0.0 {
                p.push(("orientation", r.to_vec().into()));
            }
        }
        if let Some(w) = o.downcast::<World>() {
            p.push(("children", w.child_count().into()));
            p.push(("active_camera", self.r(w.active_camera())));
            p.push(("background", self.r(w.background())));
        } else if let Some(g) = o.downcast::<Group>() {
            p.push(("children", g.child_count().into()));
        } else if let Some(c) = o.downcast::<Camera>() {
            let (kind, params) = c.get_projection_params();
            let name = match kind {
                Projection::Perspective => "perspective",
                Projection::Parallel => "parallel",
                _ => "generic",
            };
            p.push(("projection", name.into()));
            if let Some([a, aspect, near, far]) = params {
                let first = if kind == Projection::Perspective {
                    "fovy"
                } else {
                    "height"
                };
                p.push((first, a.into()));
                p.push(("aspect", aspect.into()));
                p.push(("near", near.into()));
                p.push(("far", far.into()));
            }
        } else if let Some(l) = o.downcast::<Light>() {
            let mode = match l.mode() {
                LightMode::Ambient => "ambient",
                LightMode::Directional => "directional",
                LightMode::Omni => "omni",
                LightMode::Spot => "spot",
            };
            p.push(("mode", mode.into()));
            p.push(("color", rgb(l.color()).into()));
            p.push(("intensity", l.intensity().into()));
            if l.mode() == LightMode::Spot {
                p.push(("spot_angle", l.spot_angle().into()));
                p.push(("spot_exponent", l.spot_exponent().into()));
            }
            if matches!(l.mode(), LightMode::Omni | LightMode::Spot) {
                let a = vec![
                    l.constant_attenuation(),
                    l.linear_attenuation(),
                    l.quadratic_attenuation(),
                ];
                p.push(("attenuation", a.into()));
            }
        } else if let Some(m) = o.downcast::<Mesh>() {
            let vb = m.vertex_buffer();
            p.push(("submeshes", m.submesh_count().into()));
            p.push(("vertices", vb.vertex_count().into()));
            let indices: i64 = (0..m.submesh_count())
                .filter_map(|i| m.index_buffer(i).ok())
                .map(|ib| ib.index_count() as i64)
                .sum();
            p.push(("indices", indices.into()));
            p.push(("vertex_buffer", self.r(Some(vb))));
            if let Some(s) = o.downcast::<SkinnedMesh>() {
                p.push(("skeleton", self.r(Some(s.skeleton()))));
            }
            if let Some(mm) = o.downcast::<MorphingMesh>() {
                p.push(("morph_targets", mm.morph_target_count().into()));
                p.push(("weights", mm.weights().into()));
            }
        } else if let Some(s) = o.downcast::<Sprite3D>() {
            p.push(("scaled", s.is_scaled().into()));
            let crop = vec![s.crop_x(), s.crop_y(), s.crop_width(), s.crop_height()];
            p.push(("crop", crop.into()));
            p.push(("image", self.r(Some(s.image()))));
            p.push(("appearance", self.r(s.appearance())));
        } else if let Some(a) = o.downcast::<Appearance>() {
            p.push(("layer", a.layer().into()));
            if a.material().is_some() {
                p.push(("material", self.r(a.material())));
            }
            if a.polygon_mode().is_some() {
                p.push(("polygon_mode", self.r(a.polygon_mode())));
            }
            if a.compositing_mode().is_some() {
                p.push(("compositing_mode", self.r(a.compositing_mode())));
            }
            if a.fog().is_some() {
                p.push(("fog", self.r(a.fog())));
            }
            const UNITS: [&str; 8] = [
                "texture0", "texture1", "texture2", "texture3", "texture4", "texture5", "texture6",
                "texture7",
            ];
            for (unit, name) in UNITS.iter().enumerate().take(NUM_TEXTURE_UNITS) {
                if let Ok(Some(t)) = a.texture(unit) {
                    p.push((name, self.r(Some(t))));
                }
            }
        } else if let Some(m) = o.downcast::<Material>() {
            for (name, target) in [
                ("ambient", MaterialColor::AMBIENT),
                ("diffuse", MaterialColor::DIFFUSE),
                ("emissive", MaterialColor::EMISSIVE),
                ("specular", MaterialColor::SPECULAR),
            ] {
                if let Ok(c) = m.color(target) {
                    let c = if target == MaterialColor::DIFFUSE {
                        argb(c)
                    } else {
                        rgb(c)
                    };
                    p.push((name, c.into()));
                }
            }
            p.push(("shininess", m.shininess().into()));
            p.push((
                "vertex_color_tracking",
                m.is_vertex_color_tracking_enabled().into(),
            ));
        } else if let Some(m) = o.downcast::<PolygonMode>() {
            let culling = match m.culling() {
                Culling::Back => "back",
                Culling::Front => "front",
                _ => "none",
            };
            p.push(("culling", culling.into()));
            let winding = if m.winding() == Winding::Cw {
                "cw"
            } else {
                "ccw"
            };
            p.push(("winding", winding.into()));
            let shading = if m.shading() == Shading::Flat {
                "flat"
            } else {
                "smooth"
            };
            p.push(("shading", shading.into()));
            p.push((
                "two_sided_lighting",
                m.is_two_sided_lighting_enabled().into(),
            ));
            p.push((
                "perspective_correction",
                m.is_perspective_correction_enabled().into(),
            ));
        } else if let Some(c) = o.downcast::<CompositingMode>() {
            let blending = match c.blending() {
                Blending::Alpha => "alpha",
                Blending::AlphaAdd => "alpha_add",
                Blending::Modulate => "modulate",
                Blending::ModulateX2 => "modulate_x2",
                _ => "replace",
            };
            p.push(("blending", blending.into()));
            p.push(("alpha_threshold", c.alpha_threshold().into()));
            p.push(("depth_test", c.is_depth_test_enabled().into()));
            p.push(("depth_write", c.is_depth_write_enabled().into()));
            p.push(("color_write", c.is_color_write_enabled().into()));
            p.push(("alpha_write", c.is_alpha_write_enabled().into()));
        } else if let Some(f) = o.downcast::<Fog>() {
            p.push(("color", rgb(f.color()).into()));
            if f.mode() == FogMode::Linear {
                p.push(("mode", "linear".into()));
                p.push(("near", f.near_distance().into()));
                p.push(("far", f.far_distance().into()));
            } else {
                p.push(("mode", "exponential".into()));
                p.push(("density", f.density().into()));
            }
        } else if let Some(b) = o.downcast::<Background>() {
            p.push(("color", argb(b.color()).into()));
            p.push(("color_clear", b.is_color_clear_enabled().into()));
            p.push(("depth_clear", b.is_depth_clear_enabled().into()));
            if b.image().is_some() {
                p.push(("image", self.r(b.image())));
                let mode = |m| {
                    if m == ImageMode::Repeat {
                        "repeat"
                    } else {
                        "border"
                    }
                };
                p.push((
                    "image_mode",
                    vec![mode(b.image_mode_x()), mode(b.image_mode_y())].into(),
                ));
                let crop = vec![b.crop_x(), b.crop_y(), b.crop_width(), b.crop_height()];
                p.push(("crop", crop.into()));
            }
        } else if let Some(t) = o.downcast::<Texture2D>() {
            let image = t.image();
            p.push(("image", self.r(Some(image.clone()))));
            p.push((
                "size",
                format!("{}x{}", image.width(), image.height()).into(),
            ));
            let filter = |f| match f {
                TextureFilter::BaseLevel => "base_level",
                TextureFilter::Linear => "linear",
                _ => "nearest",
            };
            p.push(("level_filter", filter(t.level_filter()).into()));
            p.push(("image_filter", filter(t.image_filter()).into()));
            let wrap = |w| {
                if w == TextureWrap::Clamp {
                    "clamp"
                } else {
                    "repeat"
                }
            };
            p.push(("wrap_s", wrap(t.wrapping_s()).into()));
            p.push(("wrap_t", wrap(t.wrapping_t()).into()));
            let func = match t.blending() {
                TextureFunction::Add => "add",
                TextureFunction::Blend => "blend",
                TextureFunction::Decal => "decal",
                TextureFunction::Modulate => "modulate",
                TextureFunction::Replace => "replace",
            };
            p.push(("blending", func.into()));
            if t.blending() == TextureFunction::Blend {
                p.push(("blend_color", rgb(t.blend_color()).into()));
            }
        } else if let Some(i) = o.downcast::<Image2D>() {
            let format = match i.format() {
                ImageFormat::Alpha => "ALPHA",
                ImageFormat::Luminance => "LUMINANCE",
                ImageFormat::LuminanceAlpha => "LUMINANCE_ALPHA",
                ImageFormat::Rgb => "RGB",
                ImageFormat::Rgba => "RGBA",
            };
            p.push(("format", format.into()));
            p.push(("width", i.width().into()));
            p.push(("height", i.height().into()));
            p.push(("mutable", i.is_mutable().into()));
        } else if let Some(v) = o.downcast::<VertexArray>() {
            p.push(("vertices", v.vertex_count().into()));
            p.push(("components", v.component_count().into()));
            p.push(("component_bytes", v.component_type().into()));
        } else if let Some(v) = o.downcast::<VertexBuffer>() {
            p.push(("vertices", v.vertex_count().into()));
            let (positions, [scale, bx, by, bz]) = v.get_positions();
            if positions.is_some() {
                p.push(("positions", self.r(positions)));
                p.push(("position_scale", scale.into()));
                p.push(("position_bias", vec![bx, by, bz].into()));
            }
            if v.normals().is_some() {
                p.push(("normals", self.r(v.normals())));
            }
            if v.colors().is_some() {
                p.push(("colors", self.r(v.colors())));
            } else {
                p.push(("default_color", argb(v.default_color()).into()));
            }
            let units = (0..NUM_TEXTURE_UNITS)
                .filter(|&u| v.get_tex_coords(u).is_ok_and(|(a, _)| a.is_some()))
                .count();
            if units > 0 {
                p.push(("texcoord_arrays", units.into()));
            }
        } else if let Some(ib) = o.downcast::<IndexBuffer>() {
            p.push(("indices", ib.index_count().into()));
        } else if let Some(k) = o.downcast::<KeyframeSequence>() {
            p.push(("keyframes", k.keyframe_count().into()));
            p.push(("components", k.component_count().into()));
            p.push((
                "interpolation",
                interpolation(k.interpolation_type()).into(),
            ));
            p.push(("repeat", repeat(k.repeat_mode()).into()));
            p.push(("duration", k.duration().into()));
            p.push((
                "valid_range",
                vec![k.valid_range_first(), k.valid_range_last()].into(),
            ));
        } else if let Some(c) = o.downcast::<AnimationController>() {
            p.extend(controller(&c));
        } else if let Some(t) = o.downcast::<AnimationTrack>() {
            p.push(("property", property(t.target_property()).into()));
            let seq = t.keyframe_sequence();
            p.push(("sequence", self.r(Some(seq.clone()))));
            p.push(("duration", seq.duration().into()));
            p.push(("repeat", repeat(seq.repeat_mode()).into()));
            match t.controller() {
                Some(c) => {
                    p.push(("controller", Val::Ref(self.idx(&c.as_object3d()))));
                    p.extend(controller(&c));
                }
                None => p.push(("controller", Val::Ref(None))),
            }
        }
        p
    }

    /// The animation section: every track with its target(s) and end, and the span.
    fn animation(&self) -> (Vec<TrackInfo>, Option<(i64, bool)>) {
        let mut all = Vec::new();
        let mut infos = Vec::new();
        for (k, e) in self.entries.iter().enumerate() {
            let Some(t) = e.obj.downcast::<AnimationTrack>() else {
                continue;
            };
            let targets = self
                .track_targets
                .get(&k)
                .map(|v| v.iter().map(|&i| self.entries[i].index).collect())
                .unwrap_or_default();
            infos.push(TrackInfo {
                index: e.index,
                targets,
                property: property(t.target_property()),
                end: scene::track_end(&t, 0),
            });
            all.push(t);
        }
        let end = scene::animation_end(&all, 0);
        (infos, end)
    }

    fn class_of(&self, index: usize) -> &'static str {
        self.entries
            .iter()
            .find(|e| e.index == index)
            .map_or("?", |e| e.obj.class_name())
    }
}

struct TrackInfo {
    index: usize,
    targets: Vec<usize>,
    property: &'static str,
    end: Option<(i64, bool)>,
}

fn controller(c: &AnimationController) -> Vec<(&'static str, Val)> {
    let (s, e) = (c.active_interval_start(), c.active_interval_end());
    let interval: Val = if s == e {
        "always".into()
    } else {
        vec![s, e].into()
    };
    vec![
        ("active_interval", interval),
        ("speed", c.speed().into()),
        ("weight", c.weight().into()),
        ("reference_world_time", c.ref_world_time().into()),
        (
            "reference_sequence_time",
            c.position(c.ref_world_time()).into(),
        ),
    ]
}

fn rgb(c: Color) -> String {
    format!("0x{:06X}", c.0 & 0xFF_FFFF)
}

fn argb(c: Color) -> String {
    format!("0x{c:08X}")
}

fn interpolation(i: Interpolation) -> &'static str {
    match i {
        Interpolation::Linear => "linear",
        Interpolation::Slerp => "slerp",
        Interpolation::Spline => "spline",
        Interpolation::Squad => "squad",
        Interpolation::Step => "step",
    }
}

fn repeat(m: RepeatMode) -> &'static str {
    match m {
        RepeatMode::Loop => "loop",
        RepeatMode::Constant => "constant",
    }
}

fn property(p: AnimationProperty) -> &'static str {
    const NAMES: [&str; 21] = [
        "ALPHA",
        "AMBIENT_COLOR",
        "COLOR",
        "CROP",
        "DENSITY",
        "DIFFUSE_COLOR",
        "EMISSIVE_COLOR",
        "FAR_DISTANCE",
        "FIELD_OF_VIEW",
        "INTENSITY",
        "MORPH_WEIGHTS",
        "NEAR_DISTANCE",
        "ORIENTATION",
        "PICKABILITY",
        "SCALE",
        "SHININESS",
        "SPECULAR_COLOR",
        "SPOT_ANGLE",
        "SPOT_EXPONENT",
        "TRANSLATION",
        "VISIBILITY",
    ];
    NAMES[(p.as_raw() - AnimationProperty::Alpha.as_raw()) as usize]
}

/// A parameter value as text: strings bare, references `#N`, the rest as compact JSON.
fn text(v: &Val) -> String {
    match v {
        Val::Ref(Some(i)) => format!("#{i}"),
        Val::Ref(None) => "none".into(),
        Val::J(Json::Str(s)) => s.clone(),
        Val::J(Json::Arr(a)) => {
            let items: Vec<String> = a.iter().map(|x| text(&Val::J(x.clone()))).collect();
            format!("[{}]", items.join(", "))
        }
        Val::J(j) => j.compact(),
    }
}

fn json(v: Val) -> Json {
    match v {
        Val::Ref(i) => i.into(),
        Val::J(j) => j,
    }
}

/// Deeper levels than this are not indented further (a chain of 100 000 Groups would
/// otherwise print gigabytes of spaces); their lines start with their depth.
const MAX_INDENT: usize = 32;

/// The text view of `loaded` (read from `path`).
pub fn text_report(path: &Path, loaded: &Loaded) -> String {
    let g = Graph::new(loaded);
    let h = &loaded.header;
    let mut out = format!(
        "{}: M3G {}.{}, {} bytes, {} objects, {} root{}{}\n",
        path.display(),
        h.version[0],
        h.version[1],
        h.total_file_size,
        loaded.objects.len(),
        g.roots.len(),
        if g.roots.len() == 1 { "" } else { "s" },
        if h.has_external_references {
            ", external references"
        } else {
            ""
        }
    );
    if !h.authoring_field.is_empty() {
        out += &format!("authoring: {}\n", h.authoring_field.escape_debug());
    }
    let mut printed = vec![false; g.entries.len()];
    let mut stack: Vec<(usize, usize)> = g.roots.iter().rev().map(|&k| (k, 0)).collect();
    while let Some((k, depth)) = stack.pop() {
        let e = &g.entries[k];
        out.extend(std::iter::repeat_n("  ", depth.min(MAX_INDENT)));
        if depth > MAX_INDENT {
            out += &format!("[depth {depth}] ");
        }
        out += &format!("#{} {}", e.index, e.obj.class_name());
        if printed[k] {
            out += " (above)\n";
            continue;
        }
        printed[k] = true;
        out += &format!(" id={}", e.obj.user_id());
        if e.external {
            out += " external";
        }
        for (name, v) in g.params(&e.obj) {
            out += &format!(" {name}={}", text(&v));
        }
        out.push('\n');
        let children: Vec<usize> = e
            .obj
            .get_references()
            .iter()
            .filter_map(|r| g.index.get(r).copied())
            .collect();
        let mut unique: Vec<usize> = Vec::new();
        for c in children {
            if !unique.contains(&c) {
                unique.push(c);
            }
        }
        stack.extend(unique.into_iter().rev().map(|c| (c, depth + 1)));
    }
    let (tracks, end) = g.animation();
    if tracks.is_empty() {
        out += "animation: none\n";
        return out;
    }
    out += &format!(
        "animation: {} track{}",
        tracks.len(),
        if tracks.len() == 1 { "" } else { "s" }
    );
    match end {
        Some((end, inclusive)) => {
            out += &format!(
                ", over {} {end} ms (--animate renders from 0 ms {} {end} ms)\n",
                if inclusive { "at" } else { "just before" },
                if inclusive {
                    "up to and including"
                } else {
                    "up to"
                },
            )
        }
        None => out += ", nothing moves from 0 ms on\n",
    }
    for t in &tracks {
        let targets: Vec<String> = t
            .targets
            .iter()
            .map(|&i| format!("#{i} {}", g.class_of(i)))
            .collect();
        let end = match t.end {
            Some((e, true)) => format!("over at {e} ms"),
            Some((e, false)) => format!("over just before {e} ms"),
            None => "changes nothing from 0 ms on".to_string(),
        };
        out += &format!(
            "  track #{} {} of {}: {end}\n",
            t.index,
            t.property,
            if targets.is_empty() {
                "nothing".to_string()
            } else {
                targets.join(", ")
            }
        );
    }
    out
}

/// The JSON view of `loaded` (read from `path`).
pub fn json_report(path: &Path, loaded: &Loaded) -> Json {
    let g = Graph::new(loaded);
    let h = &loaded.header;
    let header = Json::obj([
        (
            "version",
            format!("{}.{}", h.version[0], h.version[1]).into(),
        ),
        ("external_references", h.has_external_references.into()),
        ("total_file_size", h.total_file_size.into()),
        (
            "approximate_content_size",
            h.approximate_content_size.into(),
        ),
        ("authoring", h.authoring_field.as_str().into()),
    ]);
    let objects: Vec<Json> = g
        .entries
        .iter()
        .map(|e| {
            let params = Json::obj(g.params(&e.obj).into_iter().map(|(k, v)| (k, json(v))));
            Json::obj([
                ("index", e.index.into()),
                ("class", e.obj.class_name().into()),
                ("user_id", e.obj.user_id().into()),
                ("external", e.external.into()),
                ("params", params),
                ("references", g.refs(&e.obj).into()),
            ])
        })
        .collect();
    let (tracks, end) = g.animation();
    let tracks: Vec<Json> = tracks
        .iter()
        .map(|t| {
            Json::obj([
                ("track", t.index.into()),
                ("targets", t.targets.clone().into()),
                ("property", t.property.into()),
                ("end", t.end.map(|e| e.0).into()),
                ("end_inclusive", t.end.map(|e| e.1).into()),
            ])
        })
        .collect();
    let animation = Json::obj([
        ("tracks", Json::Arr(tracks)),
        ("start", 0.into()),
        ("end", end.map(|e| e.0).into()),
        ("end_inclusive", end.map(|e| e.1).into()),
    ]);
    Json::obj([
        ("file", path.display().to_string().into()),
        ("header", header),
        (
            "roots",
            g.roots
                .iter()
                .map(|&k| g.entries[k].index)
                .collect::<Vec<_>>()
                .into(),
        ),
        ("objects", Json::Arr(objects)),
        ("animation", animation),
    ])
}
