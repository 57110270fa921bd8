//! The ARGB color of every M3G color property.

use std::fmt;

/// A color as M3G packs it: `0xAARRGGBB`. Properties documented as RGB ignore the alpha
/// byte (and return it as 0), as the specification says.
///
/// ```
/// use m3g::Color;
///
/// let orange = Color::rgb(255, 128, 0);
/// assert_eq!(orange, Color(0xFFFF8000));
/// assert_eq!((orange.r(), orange.g(), orange.b(), orange.a()), (255, 128, 0, 255));
/// assert_eq!(Color::from(0x80FF0000).a(), 0x80);
/// assert_eq!(u32::from(Color::WHITE), 0xFFFFFFFF);
/// ```
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Color(pub u32);

impl Color {
    /// Opaque black.
    pub const BLACK: Color = Color(0xFF00_0000);
    /// Opaque white.
    pub const WHITE: Color = Color(0xFFFF_FFFF);
    /// Opaque red.
    pub const RED: Color = Color(0xFFFF_0000);
    /// Opaque green.
    pub const GREEN: Color = Color(0xFF00_FF00);
    /// Opaque blue.
    pub const BLUE: Color = Color(0xFF00_00FF);
    /// Black with zero alpha (`0x00000000`).
    pub const TRANSPARENT: Color = Color(0);

    /// An opaque color.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Color {
        Color::argb(255, r, g, b)
    }

    /// A color with alpha.
    pub const fn argb(a: u8, r: u8, g: u8, b: u8) -> Color {
        Color(u32::from_be_bytes([a, r, g, b]))
    }

    /// The alpha channel.
    pub const fn a(self) -> u8 {
        self.0.to_be_bytes()[0]
    }
    /// The red channel.
    pub const fn r(self) -> u8 {
        self.0.to_be_bytes()[1]
    }
    /// The green channel.
    pub const fn g(self) -> u8 {
        self.0.to_be_bytes()[2]
    }
    /// The blue channel.
    pub const fn b(self) -> u8 {
        self.0.to_be_bytes()[3]
    }

    /// The same color with alpha `a`.
    pub const fn with_alpha(self, a: u8) -> Color {
        Color((self.0 & 0x00FF_FFFF) | (a as u32) << 24)
    }
}

impl From<u32> for Color {
    fn from(v: u32) -> Color {
        Color(v)
    }
}

impl From<Color> for u32 {
    fn from(c: Color) -> u32 {
        c.0
    }
}

impl From<[u8; 4]> for Color {
    /// From `[r, g, b, a]`, the byte order of an RGBA pixel.
    fn from([r, g, b, a]: [u8; 4]) -> Color {
        Color::argb(a, r, g, b)
    }
}

impl From<Color> for [u8; 4] {
    /// To `[r, g, b, a]`.
    fn from(c: Color) -> [u8; 4] {
        [c.r(), c.g(), c.b(), c.a()]
    }
}

impl fmt::LowerHex for Color {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::LowerHex::fmt(&self.0, f)
    }
}

impl fmt::UpperHex for Color {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::UpperHex::fmt(&self.0, f)
    }
}

impl fmt::Debug for Color {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Color(0x{:08X})", self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::Color;

    #[test]
    fn channels_and_conversions() {
        let c = Color::argb(0x12, 0x34, 0x56, 0x78);
        assert_eq!(c.0, 0x1234_5678);
        assert_eq!([c.a(), c.r(), c.g(), c.b()], [0x12, 0x34, 0x56, 0x78]);
        assert_eq!(<[u8; 4]>::from(c), [0x34, 0x56, 0x78, 0x12]);
        assert_eq!(Color::from([0x34, 0x56, 0x78, 0x12]), c);
        assert_eq!(Color::from(0x1234_5678u32), c);
        assert_eq!(u32::from(c), 0x1234_5678);
        assert_eq!(c.with_alpha(0xFF), Color(0xFF34_5678));
        assert_eq!(Color::rgb(0, 0, 255), Color::BLUE);
        assert_eq!(format!("{:?}", Color::GREEN), "Color(0xFF00FF00)");
        assert_eq!(
            format!("{:x} {:08X}", Color(0xAB), Color(0xAB)),
            "ab 000000AB"
        );
    }
}
