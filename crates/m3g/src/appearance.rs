//! `Appearance` and its components: `CompositingMode`, `PolygonMode`, `Material`, `Fog`,
//! `Texture2D`; and `Background`.

use glam::Vec4;

use gles_cm_core::state::{AlphaTest, Blend, BlendFactor, Material as CoreMaterial, Quality};
use gles_cm_core::texenv::{self, EnvMode, FogMode as CoreFogMode, TexEnv};
use gles_cm_core::{CompareFunc, CullFace, RenderState, ShadeModel, Winding as CoreWinding};

use super::color::Color;
use super::error::{iae, ioobe, Result};
use super::image::Image2D;
use super::modes::{
    Blending, Culling, FogMode, ImageFormat, ImageMode, MaterialColor, Shading, TextureFilter,
    TextureFunction, TextureWrap, Winding,
};
use super::object::{class_data, handle, Inner, Kind, TransformableExt};
use super::vertex::NUM_TEXTURE_UNITS;

/// The largest texture width and height (`maxTextureDimension`).
pub const MAX_TEXTURE_DIMENSION: i32 = 2048;

#[derive(Clone, Debug, Default)]
pub(crate) struct AppearanceData {
    pub layer: i32,
    pub compositing_mode: Option<CompositingMode>,
    pub polygon_mode: Option<PolygonMode>,
    pub material: Option<Material>,
    pub fog: Option<Fog>,
    pub textures: [Option<Texture2D>; NUM_TEXTURE_UNITS],
}

handle!(
    /// `Appearance`: the rendering attributes of a submesh or sprite.
    Appearance,
    |i| matches!(i.kind, Kind::Appearance(_))
);
class_data!(Appearance, Appearance, AppearanceData);

impl Default for Appearance {
    fn default() -> Self {
        Appearance::new()
    }
}

impl Appearance {
    /// `Appearance()`: layer 0, every component `None`.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// // Lit, half-transparent, drawn from both sides.
    /// let material = Material::new();
    /// material.set_color(MaterialColor::DIFFUSE, Color::argb(128, 255, 200, 0))?;
    /// material.set_color(MaterialColor::AMBIENT | MaterialColor::SPECULAR, Color::WHITE)?;
    /// let blend = CompositingMode::new();
    /// blend.set_blending(Blending::Alpha);
    /// let sides = PolygonMode::new();
    /// sides.set_culling(Culling::None);
    /// let look = Appearance::new();
    /// look.set_material(Some(&material));
    /// look.set_compositing_mode(Some(&blend));
    /// look.set_polygon_mode(Some(&sides));
    /// look.set_layer(1)?; // drawn after layer 0
    /// assert_eq!(look.material().unwrap().color(MaterialColor::AMBIENT)?, Color(0x00FFFFFF));
    /// # Ok(())
    /// # }
    /// ```
    pub fn new() -> Appearance {
        Appearance(Inner::new(
            Kind::Appearance(AppearanceData::default()),
            false,
            false,
        ))
    }
    /// `setLayer(layer)`: IndexOutOfBounds unless −63 ≤ layer ≤ 63.
    pub fn set_layer(&self, layer: i32) -> Result<()> {
        if !(-63..=63).contains(&layer) {
            return ioobe("layer must be in [-63, 63]");
        }
        self.dm().layer = layer;
        Ok(())
    }
    /// `getLayer()`.
    pub fn layer(&self) -> i32 {
        self.d().layer
    }
    /// `setCompositingMode(c)`: `None` = the defaults.
    pub fn set_compositing_mode(&self, c: Option<&CompositingMode>) {
        self.dm().compositing_mode = c.cloned();
    }
    /// `getCompositingMode()`.
    pub fn compositing_mode(&self) -> Option<CompositingMode> {
        self.d().compositing_mode.clone()
    }
    /// `setPolygonMode(p)`: `None` = the defaults.
    pub fn set_polygon_mode(&self, p: Option<&PolygonMode>) {
        self.dm().polygon_mode = p.cloned();
    }
    /// `getPolygonMode()`.
    pub fn polygon_mode(&self) -> Option<PolygonMode> {
        self.d().polygon_mode.clone()
    }
    /// `setMaterial(m)`: `None` = no lighting.
    pub fn set_material(&self, m: Option<&Material>) {
        self.dm().material = m.cloned();
    }
    /// `getMaterial()`.
    pub fn material(&self) -> Option<Material> {
        self.d().material.clone()
    }
    /// `setFog(f)`: `None` = no fog.
    pub fn set_fog(&self, f: Option<&Fog>) {
        self.dm().fog = f.cloned();
    }
    /// `getFog()`.
    pub fn fog(&self) -> Option<Fog> {
        self.d().fog.clone()
    }
    /// `setTexture(unit, t)`: IndexOutOfBounds unless `unit < NUM_TEXTURE_UNITS`.
    pub fn set_texture(&self, unit: usize, t: Option<&Texture2D>) -> Result<()> {
        if unit >= NUM_TEXTURE_UNITS {
            return ioobe("texture unit index");
        }
        self.dm().textures[unit] = t.cloned();
        Ok(())
    }
    /// `getTexture(unit)`: IndexOutOfBounds for a bad unit.
    pub fn texture(&self, unit: usize) -> Result<Option<Texture2D>> {
        if unit >= NUM_TEXTURE_UNITS {
            return ioobe("texture unit index");
        }
        Ok(self.d().textures[unit].clone())
    }
}

#[derive(Clone, Debug)]
pub(crate) struct CompositingModeData {
    pub blending: Blending,
    pub alpha_threshold: f32,
    pub depth_offset: [f32; 2],
    pub depth_test: bool,
    pub depth_write: bool,
    pub color_write: bool,
    pub alpha_write: bool,
}

handle!(
    /// `CompositingMode`: blending, alpha test, depth test and writes, depth offset.
    CompositingMode,
    |i| matches!(i.kind, Kind::CompositingMode(_))
);
class_data!(CompositingMode, CompositingMode, CompositingModeData);

impl Default for CompositingMode {
    fn default() -> Self {
        CompositingMode::new()
    }
}

impl CompositingMode {
    /// `CompositingMode()`: REPLACE, threshold 0, no offset, every test and write enabled.
    pub fn new() -> CompositingMode {
        CompositingMode(Inner::new(
            Kind::CompositingMode(CompositingModeData {
                blending: Blending::Replace,
                alpha_threshold: 0.0,
                depth_offset: [0.0; 2],
                depth_test: true,
                depth_write: true,
                color_write: true,
                alpha_write: true,
            }),
            false,
            false,
        ))
    }
    /// `setBlending(mode)`.
    pub fn set_blending(&self, mode: Blending) {
        self.dm().blending = mode;
    }
    /// `getBlending()`.
    pub fn blending(&self) -> Blending {
        self.d().blending
    }
    /// `setAlphaThreshold(t)`: fragments with alpha < t are dropped. IllegalArgument unless
    /// 0 ≤ t ≤ 1.
    pub fn set_alpha_threshold(&self, t: f32) -> Result<()> {
        if !(0.0..=1.0).contains(&t) {
            return iae("alpha threshold must be in [0, 1]");
        }
        self.dm().alpha_threshold = t;
        Ok(())
    }
    /// `getAlphaThreshold()`.
    pub fn alpha_threshold(&self) -> f32 {
        self.d().alpha_threshold
    }
    /// `setDepthOffset(factor, units)`.
    pub fn set_depth_offset(&self, factor: f32, units: f32) {
        self.dm().depth_offset = [factor, units];
    }
    /// `getDepthOffsetFactor()`.
    pub fn depth_offset_factor(&self) -> f32 {
        self.d().depth_offset[0]
    }
    /// `getDepthOffsetUnits()`.
    pub fn depth_offset_units(&self) -> f32 {
        self.d().depth_offset[1]
    }
    /// `setDepthTestEnable(b)`: the test is LEQUAL.
    pub fn set_depth_test_enable(&self, enable: bool) {
        self.dm().depth_test = enable;
    }
    /// `isDepthTestEnabled()`.
    pub fn is_depth_test_enabled(&self) -> bool {
        self.d().depth_test
    }
    /// `setDepthWriteEnable(b)`: with the test off, depth is still written.
    pub fn set_depth_write_enable(&self, enable: bool) {
        self.dm().depth_write = enable;
    }
    /// `isDepthWriteEnabled()`.
    pub fn is_depth_write_enabled(&self) -> bool {
        self.d().depth_write
    }
    /// `setColorWriteEnable(b)`: red, green and blue together.
    pub fn set_color_write_enable(&self, enable: bool) {
        self.dm().color_write = enable;
    }
    /// `isColorWriteEnabled()`.
    pub fn is_color_write_enabled(&self) -> bool {
        self.d().color_write
    }
    /// `setAlphaWriteEnable(b)`.
    pub fn set_alpha_write_enable(&self, enable: bool) {
        self.dm().alpha_write = enable;
    }
    /// `isAlphaWriteEnabled()`.
    pub fn is_alpha_write_enabled(&self) -> bool {
        self.d().alpha_write
    }
}

#[derive(Clone, Debug)]
pub(crate) struct PolygonModeData {
    pub culling: Culling,
    pub winding: Winding,
    pub shading: Shading,
    pub two_sided: bool,
    pub local_camera: bool,
    pub perspective: bool,
}

handle!(
    /// `PolygonMode`: culling, winding, shading and lighting hints.
    PolygonMode,
    |i| matches!(i.kind, Kind::PolygonMode(_))
);
class_data!(PolygonMode, PolygonMode, PolygonModeData);

impl Default for PolygonMode {
    fn default() -> Self {
        PolygonMode::new()
    }
}

impl PolygonMode {
    /// `PolygonMode()`: CULL_BACK, WINDING_CCW, SHADE_SMOOTH, every flag off.
    pub fn new() -> PolygonMode {
        PolygonMode(Inner::new(
            Kind::PolygonMode(PolygonModeData {
                culling: Culling::Back,
                winding: Winding::Ccw,
                shading: Shading::Smooth,
                two_sided: false,
                local_camera: false,
                perspective: false,
            }),
            false,
            false,
        ))
    }
    /// `setCulling(mode)`.
    pub fn set_culling(&self, mode: Culling) {
        self.dm().culling = mode;
    }
    /// `getCulling()`.
    pub fn culling(&self) -> Culling {
        self.d().culling
    }
    /// `setWinding(mode)`.
    pub fn set_winding(&self, mode: Winding) {
        self.dm().winding = mode;
    }
    /// `getWinding()`.
    pub fn winding(&self) -> Winding {
        self.d().winding
    }
    /// `setShading(mode)`.
    pub fn set_shading(&self, mode: Shading) {
        self.dm().shading = mode;
    }
    /// `getShading()`.
    pub fn shading(&self) -> Shading {
        self.d().shading
    }
    /// `setTwoSidedLightingEnable(b)`.
    pub fn set_two_sided_lighting_enable(&self, enable: bool) {
        self.dm().two_sided = enable;
    }
    /// `isTwoSidedLightingEnabled()`.
    pub fn is_two_sided_lighting_enabled(&self) -> bool {
        self.d().two_sided
    }
    /// `setLocalCameraLightingEnable(b)`: a hint.
    pub fn set_local_camera_lighting_enable(&self, enable: bool) {
        self.dm().local_camera = enable;
    }
    /// `isLocalCameraLightingEnabled()`: the value set.
    pub fn is_local_camera_lighting_enabled(&self) -> bool {
        self.d().local_camera
    }
    /// `setPerspectiveCorrectionEnable(b)`: a hint.
    pub fn set_perspective_correction_enable(&self, enable: bool) {
        self.dm().perspective = enable;
    }
    /// `isPerspectiveCorrectionEnabled()`: the value set.
    pub fn is_perspective_correction_enabled(&self) -> bool {
        self.d().perspective
    }
}

#[derive(Clone, Debug)]
pub(crate) struct MaterialData {
    pub ambient: u32,
    pub diffuse: u32,
    pub emissive: u32,
    pub specular: u32,
    pub shininess: f32,
    pub tracking: bool,
}

handle!(
    /// `Material`: the colors and shininess used by lighting.
    Material,
    |i| matches!(i.kind, Kind::Material(_))
);
class_data!(Material, Material, MaterialData);

impl Default for Material {
    fn default() -> Self {
        Material::new()
    }
}

impl Material {
    /// `Material()`: ambient 0.2, diffuse 0.8 (alpha 1), emissive and specular 0,
    /// shininess 0, no vertex color tracking.
    pub fn new() -> Material {
        Material(Inner::new(
            Kind::Material(MaterialData {
                ambient: 0x0033_3333,
                diffuse: 0xFFCC_CCCC,
                emissive: 0,
                specular: 0,
                shininess: 0.0,
                tracking: false,
            }),
            false,
            false,
        ))
    }
    /// `setColor(target, ARGB)`: `target` is one or more flags ORed; alpha is kept only
    /// for DIFFUSE. IllegalArgument for no flag.
    pub fn set_color(&self, target: MaterialColor, color: Color) -> Result<()> {
        if target.is_empty() {
            return iae("invalid color target");
        }
        let c = color.0;
        let mut d = self.dm();
        if target.contains(MaterialColor::AMBIENT) {
            d.ambient = c & 0xFF_FFFF;
        }
        if target.contains(MaterialColor::DIFFUSE) {
            d.diffuse = c;
        }
        if target.contains(MaterialColor::EMISSIVE) {
            d.emissive = c & 0xFF_FFFF;
        }
        if target.contains(MaterialColor::SPECULAR) {
            d.specular = c & 0xFF_FFFF;
        }
        Ok(())
    }
    /// `getColor(target)`: IllegalArgument unless exactly one flag.
    pub fn color(&self, target: MaterialColor) -> Result<Color> {
        let d = self.d();
        Ok(Color(match target {
            MaterialColor::AMBIENT => d.ambient,
            MaterialColor::DIFFUSE => d.diffuse,
            MaterialColor::EMISSIVE => d.emissive,
            MaterialColor::SPECULAR => d.specular,
            _ => return iae("invalid color target"),
        }))
    }
    /// `setShininess(s)`: IllegalArgument unless 0 ≤ s ≤ 128.
    pub fn set_shininess(&self, s: f32) -> Result<()> {
        if !(0.0..=128.0).contains(&s) {
            return iae("shininess must be in [0, 128]");
        }
        self.dm().shininess = s;
        Ok(())
    }
    /// `getShininess()`.
    pub fn shininess(&self) -> f32 {
        self.d().shininess
    }
    /// `setVertexColorTrackingEnable(b)`: ambient and diffuse come from the vertex colors.
    pub fn set_vertex_color_tracking_enable(&self, enable: bool) {
        self.dm().tracking = enable;
    }
    /// `isVertexColorTrackingEnabled()`.
    pub fn is_vertex_color_tracking_enabled(&self) -> bool {
        self.d().tracking
    }
}

#[derive(Clone, Debug)]
pub(crate) struct FogData {
    pub mode: FogMode,
    pub density: f32,
    pub near: f32,
    pub far: f32,
    pub color: u32,
}

handle!(
    /// `Fog`: linear or exponential fog.
    Fog,
    |i| matches!(i.kind, Kind::Fog(_))
);
class_data!(Fog, Fog, FogData);

impl Default for Fog {
    fn default() -> Self {
        Fog::new()
    }
}

impl Fog {
    /// `Fog()`: LINEAR, density 1, near 0, far 1, color black.
    pub fn new() -> Fog {
        Fog(Inner::new(
            Kind::Fog(FogData {
                mode: FogMode::Linear,
                density: 1.0,
                near: 0.0,
                far: 1.0,
                color: 0,
            }),
            false,
            false,
        ))
    }
    /// `setMode(mode)`.
    pub fn set_mode(&self, mode: FogMode) {
        self.dm().mode = mode;
    }
    /// `getMode()`.
    pub fn mode(&self) -> FogMode {
        self.d().mode
    }
    /// `setLinear(near, far)`: any values (it does not change the mode).
    pub fn set_linear(&self, near: f32, far: f32) {
        let mut d = self.dm();
        d.near = near;
        d.far = far;
    }
    /// `getNearDistance()`.
    pub fn near_distance(&self) -> f32 {
        self.d().near
    }
    /// `getFarDistance()`.
    pub fn far_distance(&self) -> f32 {
        self.d().far
    }
    /// `setDensity(d)`: IllegalArgument if negative.
    pub fn set_density(&self, density: f32) -> Result<()> {
        if density < 0.0 || density.is_nan() {
            return iae("density must be non-negative");
        }
        self.dm().density = density;
        Ok(())
    }
    /// `getDensity()`.
    pub fn density(&self) -> f32 {
        self.d().density
    }
    /// `setColor(RGB)`: the alpha byte is ignored.
    pub fn set_color(&self, rgb: Color) {
        self.dm().color = rgb.0 & 0xFF_FFFF;
    }
    /// `getColor()`: 0x00RRGGBB.
    pub fn color(&self) -> Color {
        Color(self.d().color)
    }
}

#[derive(Clone, Debug)]
pub(crate) struct TextureData {
    pub image: Image2D,
    pub wrap: [TextureWrap; 2],
    pub level_filter: TextureFilter,
    pub image_filter: TextureFilter,
    pub blending: TextureFunction,
    pub blend_color: u32,
}

handle!(
    /// `Texture2D`: an image applied to a texture unit, with its own transform.
    Texture2D,
    |i| matches!(i.kind, Kind::Texture2D(_))
);
class_data!(Texture2D, Texture2D, TextureData);
impl TransformableExt for Texture2D {}

fn check_texture_image(image: &Image2D) -> Result<()> {
    let (w, h) = (image.width(), image.height());
    let pow2 = |v: i32| v > 0 && v & (v - 1) == 0;
    if !pow2(w) || !pow2(h) {
        return iae("texture dimensions must be powers of two");
    }
    if w > MAX_TEXTURE_DIMENSION || h > MAX_TEXTURE_DIMENSION {
        return iae("texture larger than maxTextureDimension");
    }
    Ok(())
}

impl Texture2D {
    /// `Texture2D(image)`: IllegalArgument unless both dimensions are powers of two no
    /// larger than `maxTextureDimension`. Defaults: REPEAT, BASE_LEVEL + NEAREST, MODULATE,
    /// blend color black.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// // A 2 × 2 checkerboard from an image buffer, repeated, filtered, modulating the color.
    /// let checker = image::RgbImage::from_fn(2, 2, |x, y| {
    ///     image::Rgb(if (x + y) % 2 == 0 { [255; 3] } else { [0; 3] })
    /// });
    /// let texture = Texture2D::new(&Image2D::try_from(&checker)?)?;
    /// texture.set_filtering(TextureFilter::BaseLevel, TextureFilter::Linear)?;
    /// texture.set_wrapping(TextureWrap::Repeat, TextureWrap::Clamp);
    /// texture.set_blending(TextureFunction::Modulate);
    /// texture.set_scale(4.0, 4.0, 1.0); // the texture transform: 4 repeats
    /// let look = Appearance::new();
    /// look.set_texture(0, Some(&texture))?;
    /// assert!(Texture2D::new(&Image2D::new(ImageFormat::Rgb, 3, 2)?).is_err()); // not 2ⁿ
    /// # Ok(())
    /// # }
    /// ```
    pub fn new(image: &Image2D) -> Result<Texture2D> {
        check_texture_image(image)?;
        Ok(Texture2D(Inner::new(
            Kind::Texture2D(TextureData {
                image: image.clone(),
                wrap: [TextureWrap::Repeat; 2],
                level_filter: TextureFilter::BaseLevel,
                image_filter: TextureFilter::Nearest,
                blending: TextureFunction::Modulate,
                blend_color: 0,
            }),
            true,
            false,
        )))
    }
    /// `setImage(image)`: the same checks as the constructor.
    pub fn set_image(&self, image: &Image2D) -> Result<()> {
        check_texture_image(image)?;
        self.dm().image = image.clone();
        Ok(())
    }
    /// `getImage()`.
    pub fn image(&self) -> Image2D {
        self.d().image.clone()
    }
    /// `setFiltering(levelFilter, imageFilter)`: IllegalArgument for an image filter other
    /// than LINEAR and NEAREST.
    pub fn set_filtering(&self, level: TextureFilter, image: TextureFilter) -> Result<()> {
        if image == TextureFilter::BaseLevel {
            return iae("invalid image filter");
        }
        let mut d = self.dm();
        d.level_filter = level;
        d.image_filter = image;
        Ok(())
    }
    /// `getLevelFilter()`.
    pub fn level_filter(&self) -> TextureFilter {
        self.d().level_filter
    }
    /// `getImageFilter()`.
    pub fn image_filter(&self) -> TextureFilter {
        self.d().image_filter
    }
    /// `setWrapping(s, t)`.
    pub fn set_wrapping(&self, s: TextureWrap, t: TextureWrap) {
        self.dm().wrap = [s, t];
    }
    /// `getWrappingS()`.
    pub fn wrapping_s(&self) -> TextureWrap {
        self.d().wrap[0]
    }
    /// `getWrappingT()`.
    pub fn wrapping_t(&self) -> TextureWrap {
        self.d().wrap[1]
    }
    /// `setBlending(func)`.
    pub fn set_blending(&self, func: TextureFunction) {
        self.dm().blending = func;
    }
    /// `getBlending()`.
    pub fn blending(&self) -> TextureFunction {
        self.d().blending
    }
    /// `setBlendColor(RGB)`: the alpha byte is ignored.
    pub fn set_blend_color(&self, rgb: Color) {
        self.dm().blend_color = rgb.0 & 0xFF_FFFF;
    }
    /// `getBlendColor()`: 0x00RRGGBB.
    pub fn blend_color(&self) -> Color {
        Color(self.d().blend_color)
    }
}

#[derive(Clone, Debug)]
pub(crate) struct BackgroundData {
    pub color_clear: bool,
    pub depth_clear: bool,
    pub color: u32,
    pub image: Option<Image2D>,
    pub mode: [ImageMode; 2],
    pub crop: [i32; 4],
}

handle!(
    /// `Background`: how Graphics3D clears the viewport (color, image, depth).
    Background,
    |i| matches!(i.kind, Kind::Background(_))
);
class_data!(Background, Background, BackgroundData);

impl Default for Background {
    fn default() -> Self {
        Background::new()
    }
}

impl Background {
    /// `Background()`: color and depth clears on, color transparent black, no image,
    /// BORDER modes.
    pub fn new() -> Background {
        Background(Inner::new(
            Kind::Background(BackgroundData {
                color_clear: true,
                depth_clear: true,
                color: 0,
                image: None,
                mode: [ImageMode::Border; 2],
                crop: [0; 4],
            }),
            false,
            false,
        ))
    }
    /// `setColorClearEnable(b)`.
    pub fn set_color_clear_enable(&self, enable: bool) {
        self.dm().color_clear = enable;
    }
    /// `isColorClearEnabled()`.
    pub fn is_color_clear_enabled(&self) -> bool {
        self.d().color_clear
    }
    /// `setDepthClearEnable(b)`.
    pub fn set_depth_clear_enable(&self, enable: bool) {
        self.dm().depth_clear = enable;
    }
    /// `isDepthClearEnabled()`.
    pub fn is_depth_clear_enabled(&self) -> bool {
        self.d().depth_clear
    }
    /// `setColor(ARGB)`.
    pub fn set_color(&self, argb: Color) {
        self.dm().color = argb.0;
    }
    /// `getColor()`.
    pub fn color(&self) -> Color {
        Color(self.d().color)
    }
    /// `setImage(image)`: resets the crop to the whole image. IllegalArgument unless the
    /// image is RGB or RGBA.
    pub fn set_image(&self, image: Option<&Image2D>) -> Result<()> {
        if let Some(i) = image {
            let f = i.format();
            if f != ImageFormat::Rgb && f != ImageFormat::Rgba {
                return iae("background images must be RGB or RGBA");
            }
        }
        let mut d = self.dm();
        if let Some(i) = image {
            d.crop = [0, 0, i.width(), i.height()];
        }
        d.image = image.cloned();
        Ok(())
    }
    /// `getImage()`.
    pub fn image(&self) -> Option<Image2D> {
        self.d().image.clone()
    }
    /// `setImageMode(modeX, modeY)`.
    pub fn set_image_mode(&self, mode_x: ImageMode, mode_y: ImageMode) {
        self.dm().mode = [mode_x, mode_y];
    }
    /// `getImageModeX()`.
    pub fn image_mode_x(&self) -> ImageMode {
        self.d().mode[0]
    }
    /// `getImageModeY()`.
    pub fn image_mode_y(&self) -> ImageMode {
        self.d().mode[1]
    }
    /// `setCrop(x, y, width, height)`: IllegalArgument for a negative width or height.
    pub fn set_crop(&self, x: i32, y: i32, width: i32, height: i32) -> Result<()> {
        if width < 0 || height < 0 {
            return iae("crop width and height must be non-negative");
        }
        self.dm().crop = [x, y, width, height];
        Ok(())
    }
    /// `getCropX()`.
    pub fn crop_x(&self) -> i32 {
        self.d().crop[0]
    }
    /// `getCropY()`.
    pub fn crop_y(&self) -> i32 {
        self.d().crop[1]
    }
    /// `getCropWidth()`.
    pub fn crop_width(&self) -> i32 {
        self.d().crop[2]
    }
    /// `getCropHeight()`.
    pub fn crop_height(&self) -> i32 {
        self.d().crop[3]
    }
}

// ---------------------------------------------------------------------------------------
// Translation into the core's state, beside the types it reads (as `gles/per_fragment.rs`
// does for GL): `Graphics3D` calls these for each submesh and sprite.

pub(crate) fn argb_to_rgba(c: u32) -> [f32; 4] {
    let f = |s: u32| ((c >> s) & 0xFF) as f32 / 255.0;
    [f(16), f(8), f(0), f(24)]
}

pub(crate) fn rgba_of(c: u32) -> Vec4 {
    Vec4::from_array(argb_to_rgba(c))
}

/// Applies a CompositingMode (or its defaults) to `s`.
pub(crate) fn apply_compositing(s: &mut RenderState, cm: Option<&CompositingMode>, depth: bool) {
    let d = cm.map(|c| c.d().clone());
    let (blending, threshold, offset, test, write, color, alpha) = match &d {
        Some(d) => (
            d.blending,
            d.alpha_threshold,
            d.depth_offset,
            d.depth_test,
            d.depth_write,
            d.color_write,
            d.alpha_write,
        ),
        None => (Blending::Replace, 0.0, [0.0; 2], true, true, true, true),
    };
    use BlendFactor::*;
    s.blend = match blending {
        Blending::Alpha => Some(Blend::func(SrcAlpha, OneMinusSrcAlpha)),
        Blending::AlphaAdd => Some(Blend::func(SrcAlpha, One)),
        Blending::Modulate => Some(Blend::func(DstColor, Zero)),
        Blending::ModulateX2 => Some(Blend::func(DstColor, SrcColor)),
        Blending::Replace => None,
    };
    if threshold > 0.0 {
        s.alpha_test = Some(AlphaTest {
            func: CompareFunc::GreaterEqual,
            reference: threshold,
        });
    }
    s.color_mask = [color, color, color, alpha];
    if depth {
        // M3G writes depth even with the test off: emulate with ALWAYS.
        s.depth_test = match (test, write) {
            (true, _) => Some(CompareFunc::LessEqual),
            (false, true) => Some(CompareFunc::Always),
            (false, false) => None,
        };
        s.depth_write = write;
        if offset != [0.0, 0.0] {
            s.polygon_offset = Some(gles_cm_core::state::PolygonOffset {
                factor: offset[0],
                units: offset[1],
                clamp: 0.0,
            });
        }
    } else {
        s.depth_test = None;
        s.depth_write = false;
    }
}

pub(crate) fn apply_polygon_mode(s: &mut RenderState, pm: Option<&PolygonMode>) {
    let (culling, winding, shading) = match pm {
        Some(p) => {
            let d = p.d();
            (d.culling, d.winding, d.shading)
        }
        None => (Culling::Back, Winding::Ccw, Shading::Smooth),
    };
    s.cull = match culling {
        Culling::Back => Some(CullFace::Back),
        Culling::Front => Some(CullFace::Front),
        Culling::None => None,
    };
    s.front_face = match winding {
        Winding::Cw => CoreWinding::Cw,
        Winding::Ccw => CoreWinding::Ccw,
    };
    s.shade_model = match shading {
        Shading::Flat => ShadeModel::Flat,
        Shading::Smooth => ShadeModel::Smooth,
    };
}

/// The core's fog for an M3G Fog: LINEAR from `near` to `far`, or EXPONENTIAL with the
/// density; the distance is |z_eye| (M3G allows that approximation), per pixel.
pub(crate) fn core_fog(f: &FogData) -> texenv::Fog {
    let [r, g, b, _] = argb_to_rgba(f.color);
    texenv::Fog {
        mode: match f.mode {
            FogMode::Linear => CoreFogMode::Linear,
            FogMode::Exponential => CoreFogMode::Exp,
        },
        density: f.density,
        start: f.near,
        end: f.far,
        color: [r, g, b, 1.0],
        quality: Quality::Balanced,
    }
}

/// The core material for an M3G Material whose lit alpha is the diffuse alpha times
/// `alpha` (without vertex color tracking; with it the tracked vertex alpha carries the
/// factor instead).
pub(crate) fn core_material(m: &MaterialData, alpha: f32) -> CoreMaterial {
    let opaque = |c: u32| rgba_of(c).truncate().extend(1.0);
    let mut diffuse = rgba_of(m.diffuse);
    if !m.tracking {
        diffuse.w *= alpha;
    }
    CoreMaterial {
        ambient: opaque(m.ambient),
        diffuse,
        specular: opaque(m.specular),
        emission: opaque(m.emissive),
        shininess: m.shininess,
    }
}

/// The core's environment for a Texture2D blending function and blend color (the M3G
/// table of §2.8 is GL's REPLACE, MODULATE, DECAL, BLEND and ADD).
pub(crate) fn tex_env(t: &TextureData) -> TexEnv {
    let [r, g, b, _] = argb_to_rgba(t.blend_color);
    TexEnv {
        mode: match t.blending {
            TextureFunction::Replace => EnvMode::Replace,
            TextureFunction::Decal => EnvMode::Decal,
            TextureFunction::Blend => EnvMode::Blend,
            TextureFunction::Add => EnvMode::Add,
            TextureFunction::Modulate => EnvMode::Modulate,
        },
        color: [r, g, b, 1.0],
    }
}
