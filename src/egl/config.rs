//! The frame buffer configurations: 36 configs, color {RGB565, RGB888, RGBA8888} × depth
//! {0, 16, 24} × stencil {0, 8} × samples {0, 4}, their attributes (EGL 1.4 table 3.1), and
//! `eglChooseConfig`'s matching and sorting rules (section 3.4.1, table 3.4). Ids 1–18 are
//! the single-sample configs, 19–36 the same list with `EGL_SAMPLE_BUFFERS` 1 and
//! `EGL_SAMPLES` 4 ([`gles_cm_core::multisample`]); the sort puts fewer samples first, so a
//! program that does not ask for samples gets a single-sample config.
#![forbid(unsafe_code)]

use std::cmp::Ordering;

use gles_cm_core::{ColorFormat, DepthFormat, TargetFormat};

use super::native::{
    EGL_MEMORY_BGRA8888, EGL_MEMORY_RGB565, EGL_MEMORY_RGB888, EGL_MEMORY_RGBA8888,
};
use super::tokens::*;
use super::types::EGLint;

/// Largest pbuffer side: the GL maximum viewport size.
pub const MAX_PBUFFER_SIDE: EGLint = 8192;
/// Largest pbuffer area.
pub const MAX_PBUFFER_PIXELS: EGLint = MAX_PBUFFER_SIDE * MAX_PBUFFER_SIDE;
/// Swap intervals accepted by eglSwapInterval (memory windows have no refresh to wait for).
pub const MIN_SWAP_INTERVAL: EGLint = 0;
pub const MAX_SWAP_INTERVAL: EGLint = 1;

/// Surface types every config supports.
pub const SURFACE_TYPES: EGLint =
    EGL_PBUFFER_BIT | EGL_PIXMAP_BIT | EGL_WINDOW_BIT | EGL_SWAP_BEHAVIOR_PRESERVED_BIT;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    /// EGL_CONFIG_ID, 1 ..= 36; also the handle value.
    pub id: EGLint,
    pub color: ColorFormat,
    pub depth: Option<DepthFormat>,
    pub stencil: EGLint,
    /// EGL_SAMPLES: 0, or [`gles_cm_core::multisample::SAMPLES`] (with one sample buffer).
    pub samples: EGLint,
}

const COLORS: [ColorFormat; 3] = [
    ColorFormat::Rgb565,
    ColorFormat::Rgb888,
    ColorFormat::Rgba8888,
];
const DEPTHS: [Option<DepthFormat>; 3] = [None, Some(DepthFormat::D16), Some(DepthFormat::D24)];

/// Every config, in config-id order.
pub fn all() -> &'static [Config] {
    static CONFIGS: std::sync::OnceLock<Vec<Config>> = std::sync::OnceLock::new();
    CONFIGS.get_or_init(|| {
        let mut v = Vec::new();
        for samples in [0, gles_cm_core::multisample::SAMPLES as EGLint] {
            for color in COLORS {
                for depth in DEPTHS {
                    for stencil in [0, 8] {
                        v.push(Config {
                            id: v.len() as EGLint + 1,
                            color,
                            depth,
                            stencil,
                            samples,
                        });
                    }
                }
            }
        }
        v
    })
}

/// The config with EGL_CONFIG_ID `id`.
pub fn by_id(id: EGLint) -> Option<&'static Config> {
    all().get((id as usize).wrapping_sub(1))
}

/// The `EGL_MEMORY_*` format a memory pixmap needs to be compatible with a color format.
pub fn native_format(color: ColorFormat) -> EGLint {
    match color {
        ColorFormat::Rgb565 => EGL_MEMORY_RGB565,
        ColorFormat::Rgb888 => EGL_MEMORY_RGB888,
        // Renderbuffer-only formats: no config has them.
        ColorFormat::Rgba8888 | ColorFormat::Rgba4444 | ColorFormat::Rgba5551 => {
            EGL_MEMORY_RGBA8888
        }
    }
}

/// True when pixels of memory format `format` hold exactly the color channels of `color`.
pub fn memory_format_matches(format: EGLint, color: ColorFormat) -> bool {
    match color {
        ColorFormat::Rgb565 => format == EGL_MEMORY_RGB565,
        ColorFormat::Rgb888 => format == EGL_MEMORY_RGB888,
        ColorFormat::Rgba8888 => format == EGL_MEMORY_RGBA8888 || format == EGL_MEMORY_BGRA8888,
        ColorFormat::Rgba4444 | ColorFormat::Rgba5551 => false,
    }
}

impl Config {
    pub fn target_format(&self) -> TargetFormat {
        TargetFormat {
            color: self.color,
            depth: self.depth,
            stencil_bits: self.stencil as u32,
        }
    }

    /// True for the configs whose surfaces keep sample planes.
    pub fn multisampled(&self) -> bool {
        self.samples > 0
    }

    fn bits(&self) -> [EGLint; 4] {
        let b = self.color.bits();
        [
            b[0] as EGLint,
            b[1] as EGLint,
            b[2] as EGLint,
            b[3] as EGLint,
        ]
    }

    /// The value of a table 3.1 attribute, or `None` for an attribute that is not one.
    pub fn attrib(&self, attribute: EGLint) -> Option<EGLint> {
        let [r, g, b, a] = self.bits();
        Some(match attribute {
            EGL_BUFFER_SIZE => r + g + b + a,
            EGL_RED_SIZE => r,
            EGL_GREEN_SIZE => g,
            EGL_BLUE_SIZE => b,
            EGL_ALPHA_SIZE => a,
            EGL_LUMINANCE_SIZE => 0,
            EGL_ALPHA_MASK_SIZE => 0,
            EGL_BIND_TO_TEXTURE_RGB => EGL_TRUE as EGLint,
            EGL_BIND_TO_TEXTURE_RGBA => (a > 0) as EGLint,
            EGL_COLOR_BUFFER_TYPE => EGL_RGB_BUFFER,
            EGL_CONFIG_CAVEAT => EGL_NONE,
            EGL_CONFIG_ID => self.id,
            EGL_CONFORMANT => EGL_OPENGL_ES_BIT,
            EGL_DEPTH_SIZE => self.depth.map_or(0, |d| d.bits() as EGLint),
            EGL_LEVEL => 0,
            EGL_MAX_PBUFFER_WIDTH | EGL_MAX_PBUFFER_HEIGHT => MAX_PBUFFER_SIDE,
            EGL_MAX_PBUFFER_PIXELS => MAX_PBUFFER_PIXELS,
            EGL_MAX_SWAP_INTERVAL => MAX_SWAP_INTERVAL,
            EGL_MIN_SWAP_INTERVAL => MIN_SWAP_INTERVAL,
            EGL_NATIVE_RENDERABLE => EGL_TRUE as EGLint,
            EGL_NATIVE_VISUAL_ID => native_format(self.color),
            EGL_NATIVE_VISUAL_TYPE => EGL_NONE,
            EGL_RENDERABLE_TYPE => EGL_OPENGL_ES_BIT,
            EGL_SAMPLE_BUFFERS => (self.samples > 0) as EGLint,
            EGL_SAMPLES => self.samples,
            EGL_STENCIL_SIZE => self.stencil,
            EGL_SURFACE_TYPE => SURFACE_TYPES,
            EGL_TRANSPARENT_TYPE => EGL_NONE,
            EGL_TRANSPARENT_RED_VALUE
            | EGL_TRANSPARENT_GREEN_VALUE
            | EGL_TRANSPARENT_BLUE_VALUE => 0,
            _ => return None,
        })
    }
}

/// How an attribute of an eglChooseConfig list selects configs (table 3.4).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Rule {
    AtLeast,
    Exact,
    Mask,
    /// Accepted and ignored (EGL_MAX_PBUFFER_*, EGL_NATIVE_VISUAL_ID).
    Ignored,
}

fn rule(attribute: EGLint) -> Option<(Rule, EGLint)> {
    use Rule::*;
    Some(match attribute {
        EGL_BUFFER_SIZE | EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE | EGL_LUMINANCE_SIZE
        | EGL_ALPHA_SIZE | EGL_ALPHA_MASK_SIZE | EGL_DEPTH_SIZE | EGL_SAMPLE_BUFFERS
        | EGL_SAMPLES | EGL_STENCIL_SIZE => (AtLeast, 0),
        EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA => (Exact, EGL_DONT_CARE),
        EGL_COLOR_BUFFER_TYPE => (Exact, EGL_RGB_BUFFER),
        EGL_CONFIG_CAVEAT | EGL_CONFIG_ID => (Exact, EGL_DONT_CARE),
        EGL_CONFORMANT => (Mask, 0),
        EGL_LEVEL => (Exact, 0),
        EGL_MAX_SWAP_INTERVAL | EGL_MIN_SWAP_INTERVAL | EGL_NATIVE_RENDERABLE => {
            (Exact, EGL_DONT_CARE)
        }
        EGL_NATIVE_VISUAL_TYPE => (Exact, EGL_DONT_CARE),
        EGL_RENDERABLE_TYPE => (Mask, EGL_OPENGL_ES_BIT),
        EGL_SURFACE_TYPE => (Mask, EGL_WINDOW_BIT),
        EGL_TRANSPARENT_TYPE => (Exact, EGL_NONE),
        EGL_TRANSPARENT_RED_VALUE | EGL_TRANSPARENT_GREEN_VALUE | EGL_TRANSPARENT_BLUE_VALUE => {
            (Exact, EGL_DONT_CARE)
        }
        EGL_MAX_PBUFFER_WIDTH
        | EGL_MAX_PBUFFER_HEIGHT
        | EGL_MAX_PBUFFER_PIXELS
        | EGL_NATIVE_VISUAL_ID => (Ignored, EGL_DONT_CARE),
        _ => return None,
    })
}

const API_BITS: EGLint = EGL_OPENGL_ES_BIT | EGL_OPENVG_BIT | EGL_OPENGL_ES2_BIT | EGL_OPENGL_BIT;
const SURFACE_BITS: EGLint = EGL_PBUFFER_BIT
    | EGL_PIXMAP_BIT
    | EGL_WINDOW_BIT
    | EGL_VG_COLORSPACE_LINEAR_BIT
    | EGL_VG_ALPHA_FORMAT_PRE_BIT
    | EGL_MULTISAMPLE_RESOLVE_BOX_BIT
    | EGL_SWAP_BEHAVIOR_PRESERVED_BIT;

/// Whether `value` is acceptable for `attribute` in an eglChooseConfig list.
fn value_ok(attribute: EGLint, value: EGLint) -> bool {
    if value == EGL_DONT_CARE {
        // Table 3.4: every attribute but EGL_LEVEL (and EGL_MATCH_NATIVE_PIXMAP) may be
        // EGL_DONT_CARE.
        return attribute != EGL_LEVEL;
    }
    match attribute {
        EGL_BUFFER_SIZE
        | EGL_RED_SIZE
        | EGL_GREEN_SIZE
        | EGL_BLUE_SIZE
        | EGL_LUMINANCE_SIZE
        | EGL_ALPHA_SIZE
        | EGL_ALPHA_MASK_SIZE
        | EGL_DEPTH_SIZE
        | EGL_SAMPLE_BUFFERS
        | EGL_SAMPLES
        | EGL_STENCIL_SIZE
        | EGL_MAX_SWAP_INTERVAL
        | EGL_MIN_SWAP_INTERVAL => value >= 0,
        EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA | EGL_NATIVE_RENDERABLE => {
            value == EGL_TRUE as EGLint || value == EGL_FALSE as EGLint
        }
        EGL_COLOR_BUFFER_TYPE => value == EGL_RGB_BUFFER || value == EGL_LUMINANCE_BUFFER,
        EGL_CONFIG_CAVEAT => {
            matches!(
                value,
                EGL_NONE | EGL_SLOW_CONFIG | EGL_NON_CONFORMANT_CONFIG
            )
        }
        EGL_CONFORMANT | EGL_RENDERABLE_TYPE => value & !API_BITS == 0,
        EGL_SURFACE_TYPE => value & !SURFACE_BITS == 0,
        EGL_TRANSPARENT_TYPE => value == EGL_NONE || value == EGL_TRANSPARENT_RGB,
        _ => true,
    }
}

/// A parsed eglChooseConfig attribute list.
#[derive(Clone, Debug)]
pub struct Criteria {
    /// The value of every table 3.4 attribute (defaults where the list has none).
    values: Vec<(EGLint, EGLint)>,
    /// EGL_MATCH_NATIVE_PIXMAP's value, when given and not EGL_NONE.
    pub match_native_pixmap: Option<EGLint>,
}

const ALL_ATTRIBUTES: &[EGLint] = &[
    EGL_BUFFER_SIZE,
    EGL_RED_SIZE,
    EGL_GREEN_SIZE,
    EGL_BLUE_SIZE,
    EGL_LUMINANCE_SIZE,
    EGL_ALPHA_SIZE,
    EGL_ALPHA_MASK_SIZE,
    EGL_BIND_TO_TEXTURE_RGB,
    EGL_BIND_TO_TEXTURE_RGBA,
    EGL_COLOR_BUFFER_TYPE,
    EGL_CONFIG_CAVEAT,
    EGL_CONFIG_ID,
    EGL_CONFORMANT,
    EGL_DEPTH_SIZE,
    EGL_LEVEL,
    EGL_MAX_PBUFFER_WIDTH,
    EGL_MAX_PBUFFER_HEIGHT,
    EGL_MAX_PBUFFER_PIXELS,
    EGL_MAX_SWAP_INTERVAL,
    EGL_MIN_SWAP_INTERVAL,
    EGL_NATIVE_RENDERABLE,
    EGL_NATIVE_VISUAL_ID,
    EGL_NATIVE_VISUAL_TYPE,
    EGL_RENDERABLE_TYPE,
    EGL_SAMPLE_BUFFERS,
    EGL_SAMPLES,
    EGL_STENCIL_SIZE,
    EGL_SURFACE_TYPE,
    EGL_TRANSPARENT_TYPE,
    EGL_TRANSPARENT_RED_VALUE,
    EGL_TRANSPARENT_GREEN_VALUE,
    EGL_TRANSPARENT_BLUE_VALUE,
];

impl Criteria {
    /// Parses `(attribute, value)` pairs (the list up to EGL_NONE). Unknown attributes and
    /// invalid values give EGL_BAD_ATTRIBUTE.
    pub fn parse(pairs: &[(EGLint, EGLint)]) -> Result<Criteria, EGLint> {
        let mut values: Vec<(EGLint, EGLint)> = ALL_ATTRIBUTES
            .iter()
            .map(|&a| (a, rule(a).expect("table attribute").1))
            .collect();
        let mut match_native_pixmap = None;
        for &(attribute, value) in pairs {
            if attribute == EGL_MATCH_NATIVE_PIXMAP {
                if value == EGL_DONT_CARE {
                    return Err(EGL_BAD_ATTRIBUTE);
                }
                match_native_pixmap = (value != EGL_NONE).then_some(value);
                continue;
            }
            if rule(attribute).is_none() || !value_ok(attribute, value) {
                return Err(EGL_BAD_ATTRIBUTE);
            }
            if let Some(slot) = values.iter_mut().find(|(a, _)| *a == attribute) {
                slot.1 = value;
            }
        }
        Ok(Criteria {
            values,
            match_native_pixmap,
        })
    }

    /// The requested value of `attribute` (its default when the list had none).
    pub fn get(&self, attribute: EGLint) -> EGLint {
        self.values
            .iter()
            .find(|(a, _)| *a == attribute)
            .map_or(EGL_DONT_CARE, |&(_, v)| v)
    }

    /// Whether `config` satisfies every criterion (EGL_MATCH_NATIVE_PIXMAP is checked by the
    /// caller, which can read the pixmap). EGL_CONFIG_ID, when given, overrides the rest.
    pub fn matches(&self, config: &Config) -> bool {
        let id = self.get(EGL_CONFIG_ID);
        if id != EGL_DONT_CARE {
            return config.id == id;
        }
        self.values.iter().all(|&(attribute, want)| {
            let (rule, _) = rule(attribute).expect("table attribute");
            if want == EGL_DONT_CARE || rule == Rule::Ignored {
                return true;
            }
            let have = config.attrib(attribute).expect("table attribute");
            match rule {
                Rule::AtLeast => have >= want,
                Rule::Exact => have == want,
                Rule::Mask => have & want == want,
                Rule::Ignored => true,
            }
        })
    }

    /// The sum of the color component sizes the list asked for (nonzero, not DONT_CARE),
    /// counted in `config` (sort rule 3).
    fn requested_color_bits(&self, config: &Config) -> EGLint {
        let attrs: &[EGLint] = if self.get(EGL_COLOR_BUFFER_TYPE) == EGL_LUMINANCE_BUFFER {
            &[EGL_LUMINANCE_SIZE, EGL_ALPHA_SIZE]
        } else {
            &[EGL_RED_SIZE, EGL_GREEN_SIZE, EGL_BLUE_SIZE, EGL_ALPHA_SIZE]
        };
        attrs
            .iter()
            .filter(|&&a| {
                let v = self.get(a);
                v != 0 && v != EGL_DONT_CARE
            })
            .map(|&a| config.attrib(a).unwrap_or(0))
            .sum()
    }

    /// Section 3.4.1's sort order: `Less` when `a` comes first.
    pub fn compare(&self, a: &Config, b: &Config) -> Ordering {
        let at = |c: &Config, attr| c.attrib(attr).expect("table attribute");
        let caveat_rank = |c: &Config| match at(c, EGL_CONFIG_CAVEAT) {
            EGL_NONE => 0,
            EGL_SLOW_CONFIG => 1,
            _ => 2,
        };
        let buffer_rank = |c: &Config| (at(c, EGL_COLOR_BUFFER_TYPE) != EGL_RGB_BUFFER) as i32;
        caveat_rank(a)
            .cmp(&caveat_rank(b))
            .then(buffer_rank(a).cmp(&buffer_rank(b)))
            .then(
                self.requested_color_bits(b)
                    .cmp(&self.requested_color_bits(a)),
            )
            .then(at(a, EGL_BUFFER_SIZE).cmp(&at(b, EGL_BUFFER_SIZE)))
            .then(at(a, EGL_SAMPLE_BUFFERS).cmp(&at(b, EGL_SAMPLE_BUFFERS)))
            .then(at(a, EGL_SAMPLES).cmp(&at(b, EGL_SAMPLES)))
            .then(at(a, EGL_DEPTH_SIZE).cmp(&at(b, EGL_DEPTH_SIZE)))
            .then(at(a, EGL_STENCIL_SIZE).cmp(&at(b, EGL_STENCIL_SIZE)))
            .then(at(a, EGL_ALPHA_MASK_SIZE).cmp(&at(b, EGL_ALPHA_MASK_SIZE)))
            .then(at(a, EGL_NATIVE_VISUAL_TYPE).cmp(&at(b, EGL_NATIVE_VISUAL_TYPE)))
            .then(a.id.cmp(&b.id))
    }

    /// The configs matching the criteria, best first. `pixmap_ok` answers
    /// EGL_MATCH_NATIVE_PIXMAP for a config (called only when that attribute was given).
    pub fn choose(&self, pixmap_ok: impl Fn(&Config) -> bool) -> Vec<&'static Config> {
        let mut v: Vec<&'static Config> = all()
            .iter()
            .filter(|c| self.matches(c))
            .filter(|c| self.match_native_pixmap.is_none() || pixmap_ok(c))
            .collect();
        v.sort_by(|a, b| self.compare(a, b));
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn choose(pairs: &[(EGLint, EGLint)]) -> Vec<EGLint> {
        Criteria::parse(pairs)
            .unwrap()
            .choose(|_| true)
            .iter()
            .map(|c| c.id)
            .collect()
    }

    #[test]
    fn thirty_six_configs_with_consistent_attributes() {
        assert_eq!(all().len(), 36);
        for (i, c) in all().iter().enumerate() {
            assert_eq!(c.id as usize, i + 1);
            let sum: EGLint = [EGL_RED_SIZE, EGL_GREEN_SIZE, EGL_BLUE_SIZE, EGL_ALPHA_SIZE]
                .iter()
                .map(|&a| c.attrib(a).unwrap())
                .sum();
            assert_eq!(c.attrib(EGL_BUFFER_SIZE), Some(sum));
            for &a in ALL_ATTRIBUTES {
                assert!(c.attrib(a).is_some(), "attribute {a:#x}");
            }
        }
        assert_eq!(by_id(0), None);
        assert_eq!(by_id(37), None);
        for c in &all()[18..] {
            let single = by_id(c.id - 18).unwrap();
            assert_eq!(
                (c.color, c.depth, c.stencil),
                (single.color, single.depth, single.stencil)
            );
            assert_eq!(c.attrib(EGL_SAMPLE_BUFFERS), Some(1));
            assert_eq!(c.attrib(EGL_SAMPLES), Some(4));
            assert_eq!(single.attrib(EGL_SAMPLES), Some(0));
        }
        assert_eq!(all()[0].attrib(0x1234), None);
    }

    #[test]
    fn default_criteria_want_window_es_and_sort_by_size() {
        let ids = choose(&[]);
        assert_eq!(ids.len(), 36);
        // No color sizes requested: smaller buffers first, then fewer samples, then smaller
        // depth and stencil.
        assert_eq!(&ids[..6], &[1, 2, 3, 4, 5, 6]);
        assert_eq!(&ids[6..12], &[19, 20, 21, 22, 23, 24]);
        assert_eq!(ids[12], 7);
    }

    #[test]
    fn requested_color_bits_put_deeper_configs_first() {
        let ids = choose(&[(EGL_RED_SIZE, 1)]);
        assert_eq!(ids.len(), 36);
        // RGB888 (24 bits) and RGBA8888 (red 8) beat RGB565 (red 5); among equal red bits
        // the smaller buffer wins, then fewer samples.
        assert_eq!(ids[0], 7);
        assert_eq!(ids[6], 25);
        assert_eq!(ids[12], 13);
        assert_eq!(ids[24], 1);
        let ids = choose(&[(EGL_ALPHA_SIZE, 1)]);
        assert_eq!(ids, vec![13, 14, 15, 16, 17, 18, 31, 32, 33, 34, 35, 36]);
        // Asking for samples gets only the multisampled configs, in the same order.
        let ids = choose(&[(EGL_SAMPLE_BUFFERS, 1), (EGL_SAMPLES, 4)]);
        assert_eq!(ids.len(), 18);
        assert_eq!(&ids[..6], &[19, 20, 21, 22, 23, 24]);
    }

    #[test]
    fn at_least_exact_mask_and_dont_care() {
        assert_eq!(choose(&[(EGL_DEPTH_SIZE, 17)]).len(), 12);
        assert_eq!(choose(&[(EGL_DEPTH_SIZE, EGL_DONT_CARE)]).len(), 36);
        assert_eq!(choose(&[(EGL_LEVEL, 1)]).len(), 0);
        assert_eq!(
            choose(&[(EGL_SURFACE_TYPE, EGL_PIXMAP_BIT | EGL_PBUFFER_BIT)]).len(),
            36
        );
        assert_eq!(choose(&[(EGL_RENDERABLE_TYPE, EGL_OPENVG_BIT)]).len(), 0);
        assert_eq!(choose(&[(EGL_BIND_TO_TEXTURE_RGBA, 1)]).len(), 12);
        assert_eq!(
            choose(&[(EGL_COLOR_BUFFER_TYPE, EGL_LUMINANCE_BUFFER)]).len(),
            0
        );
        assert_eq!(choose(&[(EGL_CONFIG_CAVEAT, EGL_SLOW_CONFIG)]).len(), 0);
        assert_eq!(choose(&[(EGL_SAMPLES, 1)]).len(), 18);
        assert_eq!(choose(&[(EGL_SAMPLES, 5)]).len(), 0);
        assert_eq!(choose(&[(EGL_SAMPLE_BUFFERS, 2)]).len(), 0);
    }

    #[test]
    fn config_id_overrides_everything_else() {
        assert_eq!(choose(&[(EGL_CONFIG_ID, 5), (EGL_LEVEL, 3)]), vec![5]);
        assert_eq!(choose(&[(EGL_CONFIG_ID, 99)]), Vec::<EGLint>::new());
    }

    #[test]
    fn later_duplicates_win_and_depth_sorts_smaller_first() {
        let ids = choose(&[(EGL_DEPTH_SIZE, 24), (EGL_DEPTH_SIZE, 1), (EGL_RED_SIZE, 8)]);
        assert_eq!(ids[0], 9); // RGB888, depth 16, stencil 0
    }

    #[test]
    fn bad_attributes_and_values() {
        for pairs in [
            &[(0x1234, 0)][..],
            &[(EGL_RED_SIZE, -5)],
            &[(EGL_COLOR_BUFFER_TYPE, 7)],
            &[(EGL_CONFIG_CAVEAT, 7)],
            &[(EGL_SURFACE_TYPE, 0x10000)],
            &[(EGL_RENDERABLE_TYPE, 0x100)],
            &[(EGL_BIND_TO_TEXTURE_RGB, 2)],
            &[(EGL_TRANSPARENT_TYPE, 3)],
            &[(EGL_LEVEL, EGL_DONT_CARE)],
            &[(EGL_MATCH_NATIVE_PIXMAP, EGL_DONT_CARE)],
        ] {
            assert_eq!(
                Criteria::parse(pairs).unwrap_err(),
                EGL_BAD_ATTRIBUTE,
                "{pairs:?}"
            );
        }
    }

    #[test]
    fn native_pixmap_match_filters() {
        let c = Criteria::parse(&[(EGL_MATCH_NATIVE_PIXMAP, 1234)]).unwrap();
        assert_eq!(c.match_native_pixmap, Some(1234));
        let ids: Vec<_> = c
            .choose(|c| memory_format_matches(EGL_MEMORY_RGB565, c.color))
            .iter()
            .map(|c| c.id)
            .collect();
        assert_eq!(ids, vec![1, 2, 3, 4, 5, 6, 19, 20, 21, 22, 23, 24]);
    }
}
