//! The specification's mode and flag constants as Rust types. Each keeps the numeric value
//! of the specification (and of the file format): `as_raw` gives it, `from_raw` (and
//! `TryFrom<i32>`) takes it back and refuses any other value with IllegalArgument, the
//! error a Java call would throw for it.

use std::fmt;
use std::ops::{BitOr, BitOrAssign};

use super::error::{iae, Error, Result};

/// Declares a mode enum with its raw-value conversions.
macro_rules! raw_enum {
    ($(#[$m:meta])* $Name:ident, $what:literal { $($(#[$vm:meta])* $V:ident = $n:literal,)* }) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $Name {
            $($(#[$vm])* $V = $n,)*
        }

        impl $Name {
            /// Every value, in the specification's numeric order.
            pub const ALL: &'static [$Name] = &[$($Name::$V),*];

            /// The specification's numeric value.
            pub const fn as_raw(self) -> i32 {
                self as i32
            }

            /// The value with the specification's number `v`; IllegalArgument for any other.
            pub fn from_raw(v: i32) -> Result<$Name> {
                match v {
                    $($n => Ok($Name::$V),)*
                    _ => iae(format!(concat!("{} is not a valid ", $what), v)),
                }
            }
        }

        impl TryFrom<i32> for $Name {
            type Error = Error;
            fn try_from(v: i32) -> Result<$Name> {
                $Name::from_raw(v)
            }
        }

        impl From<$Name> for i32 {
            fn from(v: $Name) -> i32 {
                v.as_raw()
            }
        }
    };
}

/// Declares an OR-able flags type with its raw-value conversions.
macro_rules! raw_flags {
    (
        $(#[$m:meta])* $Name:ident, $what:literal {
            $($(#[$cm:meta])* $C:ident = $n:literal,)*
        }
    ) => {
        $(#[$m])*
        #[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
        pub struct $Name(i32);

        impl $Name {
            $($(#[$cm])* pub const $C: $Name = $Name($n);)*
            const NAMES: &'static [(&'static str, $Name)] = &[$((stringify!($C), $Name::$C)),*];

            /// No flag.
            pub const fn empty() -> $Name {
                $Name(0)
            }

            /// Whether no flag is set.
            pub const fn is_empty(self) -> bool {
                self.0 == 0
            }

            /// Whether every flag of `other` is set.
            pub const fn contains(self, other: $Name) -> bool {
                self.0 & other.0 == other.0
            }

            /// The specification's numeric value (the flags ORed).
            pub const fn as_raw(self) -> i32 {
                self.0
            }

            /// The flags of `v`; IllegalArgument if it has a bit no flag uses.
            pub fn from_raw(v: i32) -> Result<$Name> {
                let all = 0 $(| $n)*;
                if v & !all != 0 {
                    return iae(format!(concat!("{} is not a valid ", $what), v));
                }
                Ok($Name(v))
            }
        }

        impl BitOr for $Name {
            type Output = $Name;
            fn bitor(self, o: $Name) -> $Name {
                $Name(self.0 | o.0)
            }
        }

        impl BitOrAssign for $Name {
            fn bitor_assign(&mut self, o: $Name) {
                self.0 |= o.0;
            }
        }

        impl TryFrom<i32> for $Name {
            type Error = Error;
            fn try_from(v: i32) -> Result<$Name> {
                $Name::from_raw(v)
            }
        }

        impl From<$Name> for i32 {
            fn from(v: $Name) -> i32 {
                v.0
            }
        }

        impl fmt::Debug for $Name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                let set: Vec<&str> = Self::NAMES
                    .iter()
                    .filter(|(_, v)| self.contains(*v))
                    .map(|(n, _)| *n)
                    .collect();
                let shown = if set.is_empty() { "empty".to_string() } else { set.join(" | ") };
                write!(f, "{}({shown})", stringify!($Name))
            }
        }
    };
}

raw_enum!(
    /// `Light.AMBIENT` … `SPOT`: what a [`Light`](crate::Light) is.
    LightMode, "light mode" {
        /// Ambient light.
        Ambient = 128,
        /// Directional light, shining along the node's −Z.
        Directional = 129,
        /// A point light at the node's origin.
        Omni = 130,
        /// A spot light at the origin, pointing along −Z.
        Spot = 131,
    }
);

raw_enum!(
    /// `Camera.GENERIC` / `PARALLEL` / `PERSPECTIVE`: a [`Camera`](crate::Camera)'s
    /// projection.
    Projection, "projection" {
        /// A projection given as a matrix.
        Generic = 48,
        /// A parallel projection.
        Parallel = 49,
        /// A perspective projection.
        Perspective = 50,
    }
);

raw_enum!(
    /// `KeyframeSequence.LINEAR` … `STEP`: how a
    /// [`KeyframeSequence`](crate::KeyframeSequence) interpolates between keys.
    Interpolation, "interpolation" {
        /// Linear interpolation.
        Linear = 176,
        /// Spherical linear interpolation of quaternions (4 components).
        Slerp = 177,
        /// Catmull-Rom spline with the specification's tangent scaling for uneven key spacing.
        Spline = 178,
        /// Spline interpolation of quaternions (4 components).
        Squad = 179,
        /// Each key's value holds until the next key.
        Step = 180,
    }
);

raw_enum!(
    /// `KeyframeSequence.CONSTANT` / `LOOP`: what a sequence does outside its duration.
    RepeatMode, "repeat mode" {
        /// Play once: before the first valid key its value, after the last its value.
        Constant = 192,
        /// Repeat every `duration`, interpolating across the wrap.
        Loop = 193,
    }
);

raw_enum!(
    /// `Image2D.ALPHA` … `RGBA`: the channels of an [`Image2D`](crate::Image2D).
    ImageFormat, "image format" {
        /// Alpha only.
        Alpha = 96,
        /// Luminance only.
        Luminance = 97,
        /// Luminance, then alpha.
        LuminanceAlpha = 98,
        /// Red, green, blue.
        Rgb = 99,
        /// Red, green, blue, alpha.
        Rgba = 100,
    }
);

raw_enum!(
    /// `CompositingMode.ALPHA` … `REPLACE`: how a fragment is blended into the target.
    Blending, "blending mode" {
        /// Cd = Cs·As + Cd·(1 − As).
        Alpha = 64,
        /// Cd = Cs·As + Cd.
        AlphaAdd = 65,
        /// Cd = Cs·Cd.
        Modulate = 66,
        /// Cd = 2·Cs·Cd.
        ModulateX2 = 67,
        /// Cd = Cs.
        Replace = 68,
    }
);

raw_enum!(
    /// `PolygonMode.CULL_*`: which faces are not drawn.
    Culling, "culling mode" {
        /// Cull back faces.
        Back = 160,
        /// Cull front faces.
        Front = 161,
        /// Cull nothing.
        None = 162,
    }
);

raw_enum!(
    /// `PolygonMode.SHADE_*`.
    Shading, "shading mode" {
        /// Flat shading (the third vertex's color).
        Flat = 164,
        /// Smooth shading.
        Smooth = 165,
    }
);

raw_enum!(
    /// `PolygonMode.WINDING_*`: which polygons are front faces.
    Winding, "winding" {
        /// Counter-clockwise polygons are front faces.
        Ccw = 168,
        /// Clockwise polygons are front faces.
        Cw = 169,
    }
);

raw_enum!(
    /// `Fog.EXPONENTIAL` / `LINEAR`.
    FogMode, "fog mode" {
        /// f = e^(−density·z).
        Exponential = 80,
        /// f = (far − z) / (far − near).
        Linear = 81,
    }
);

raw_enum!(
    /// `Texture2D.FILTER_*`: the level (mipmap) and image filters.
    TextureFilter, "texture filter" {
        /// The base level only.
        BaseLevel = 208,
        /// Linear.
        Linear = 209,
        /// Nearest.
        Nearest = 210,
    }
);

raw_enum!(
    /// `Texture2D.FUNC_*`: how a texture combines with the incoming color.
    TextureFunction, "texture blending function" {
        /// Add.
        Add = 224,
        /// Blend with the blend color.
        Blend = 225,
        /// Decal.
        Decal = 226,
        /// Modulate.
        Modulate = 227,
        /// Replace.
        Replace = 228,
    }
);

raw_enum!(
    /// `Texture2D.WRAP_*`.
    TextureWrap, "texture wrapping" {
        /// Clamp to [0, 1].
        Clamp = 240,
        /// Repeat.
        Repeat = 241,
    }
);

raw_enum!(
    /// `Background.BORDER` / `REPEAT`: what a background image shows outside itself.
    ImageMode, "background image mode" {
        /// Outside the image: the background color.
        Border = 32,
        /// Outside the image: the image repeated.
        Repeat = 33,
    }
);

raw_enum!(
    /// `Node.NONE` … `Z_AXIS`: an alignment target.
    AlignTarget, "alignment target" {
        /// No alignment.
        None = 144,
        /// The reference node's origin.
        Origin = 145,
        /// The reference node's X axis.
        XAxis = 146,
        /// The reference node's Y axis.
        YAxis = 147,
        /// The reference node's Z axis.
        ZAxis = 148,
    }
);

raw_enum!(
    /// `AnimationTrack.ALPHA` … `VISIBILITY`: the property an
    /// [`AnimationTrack`](crate::AnimationTrack) animates.
    AnimationProperty, "animation property" {
        /// Node alpha factor; alpha of Background color, Material diffuse color or
        /// VertexBuffer default color. 1 component.
        Alpha = 256,
        /// Material ambient color. 3 components.
        AmbientColor = 257,
        /// Light, Background, Fog color; Texture2D blend color; VertexBuffer default RGB.
        /// 3 components.
        Color = 258,
        /// Sprite3D or Background crop: 2 (x, y) or 4 (x, y, w, h) components.
        Crop = 259,
        /// Fog density. 1 component.
        Density = 260,
        /// Material diffuse color. 3 components.
        DiffuseColor = 261,
        /// Material emissive color. 3 components.
        EmissiveColor = 262,
        /// Camera or Fog far distance. 1 component.
        FarDistance = 263,
        /// Camera field of view (or parallel height). 1 component.
        FieldOfView = 264,
        /// Light intensity. 1 component.
        Intensity = 265,
        /// MorphingMesh weights. Any number of components.
        MorphWeights = 266,
        /// Camera or Fog near distance. 1 component.
        NearDistance = 267,
        /// Transformable orientation, a quaternion (x, y, z, w). 4 components.
        Orientation = 268,
        /// Node picking enable (≥ 0.5 = on). 1 component.
        Pickability = 269,
        /// Transformable scale: 1 (uniform) or 3 components.
        Scale = 270,
        /// Material shininess. 1 component.
        Shininess = 271,
        /// Material specular color. 3 components.
        SpecularColor = 272,
        /// Light spot angle. 1 component.
        SpotAngle = 273,
        /// Light spot exponent. 1 component.
        SpotExponent = 274,
        /// Transformable translation. 3 components.
        Translation = 275,
        /// Node rendering enable (≥ 0.5 = on). 1 component.
        Visibility = 276,
    }
);

raw_flags!(
    /// `Material.AMBIENT` … `SPECULAR`: which of a [`Material`](crate::Material)'s colors a
    /// call sets; OR them to set several at once.
    MaterialColor, "material color target" {
        /// The ambient color.
        AMBIENT = 1024,
        /// The diffuse color.
        DIFFUSE = 2048,
        /// The emissive color.
        EMISSIVE = 4096,
        /// The specular color.
        SPECULAR = 8192,
    }
);

raw_flags!(
    /// `Graphics3D.ANTIALIAS` … `OVERWRITE`: the rendering hints of
    /// [`Graphics3D::bind_target`](crate::Graphics3D::bind_target), ORed.
    RenderHints, "rendering hint" {
        /// Antialiasing.
        ANTIALIAS = 2,
        /// Dithering.
        DITHER = 4,
        /// High-precision color.
        TRUE_COLOR = 8,
        /// The target's previous contents need not be kept.
        OVERWRITE = 16,
    }
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn enums_round_trip_their_raw_values_and_refuse_others() {
        for &m in LightMode::ALL {
            assert_eq!(LightMode::from_raw(m.as_raw()), Ok(m));
        }
        assert_eq!(AnimationProperty::ALL.len(), 21);
        for &p in AnimationProperty::ALL {
            assert_eq!(AnimationProperty::try_from(i32::from(p)), Ok(p));
        }
        assert_eq!(Blending::Alpha.as_raw(), 64);
        assert_eq!(Culling::None.as_raw(), 162);
        assert_eq!(ImageFormat::from_raw(99), Ok(ImageFormat::Rgb));
        for bad in [0, 127, 132, -1] {
            assert!(matches!(
                LightMode::from_raw(bad),
                Err(Error::IllegalArgument(_))
            ));
        }
        assert!(matches!(
            Shading::from_raw(163),
            Err(Error::IllegalArgument(_))
        ));
    }

    #[test]
    fn flags_combine_and_refuse_unknown_bits() {
        let both = MaterialColor::AMBIENT | MaterialColor::DIFFUSE;
        assert_eq!(both.as_raw(), 3072);
        assert!(both.contains(MaterialColor::DIFFUSE));
        assert!(!both.contains(MaterialColor::SPECULAR));
        assert_eq!(MaterialColor::from_raw(3072), Ok(both));
        assert!(matches!(
            MaterialColor::from_raw(1),
            Err(Error::IllegalArgument(_))
        ));
        assert_eq!(format!("{both:?}"), "MaterialColor(AMBIENT | DIFFUSE)");
        assert_eq!(format!("{:?}", RenderHints::empty()), "RenderHints(empty)");
        let mut h = RenderHints::DITHER;
        h |= RenderHints::OVERWRITE;
        assert_eq!(RenderHints::try_from(20), Ok(h));
    }
}
