//! `Mesh` and `Sprite3D`.

use super::appearance::Appearance;
use super::error::{iae, ioobe, Result};
use super::image::Image2D;
use super::node::NodeExt;
use super::object::{class_data, handle, Inner, Kind, TransformableExt};
use super::vertex::{IndexBuffer, VertexBuffer};

/// The largest sprite crop width and height (`maxSpriteCropDimension`).
pub const MAX_SPRITE_CROP_DIMENSION: i32 = 1024;

#[derive(Clone, Debug)]
pub(crate) struct MeshData {
    pub vb: VertexBuffer,
    pub ibs: Vec<IndexBuffer>,
    pub apps: Vec<Option<Appearance>>,
    /// The MorphingMesh / SkinnedMesh part.
    pub ext: super::deform::MeshExt,
}

handle!(
    /// `Mesh`: a vertex buffer drawn as one or more submeshes (index buffer + appearance).
    Mesh,
    |i| matches!(i.kind, Kind::Mesh(_))
);
class_data!(Mesh, Mesh, MeshData);
impl TransformableExt for Mesh {}
impl NodeExt for Mesh {}

impl Mesh {
    /// `Mesh(vertices, triangles, appearance)`: one submesh.
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// let positions = VertexArray::new(3, 3, 1)?;
    /// positions.set_bytes(0, &[0, 0, 0, 1, 0, 0, 0, 1, 0])?;
    /// let vertices = VertexBuffer::new();
    /// vertices.set_positions(Some(&positions), 1.0, None)?;
    /// let triangle = TriangleStripArray::new_implicit(0, &[3])?;
    /// let mesh = Mesh::new(&vertices, &triangle, Some(&Appearance::new()));
    /// assert_eq!(mesh.submesh_count(), 1);
    /// assert_eq!(mesh.index_buffer(0)?.indices(), [0, 1, 2]);
    /// # Ok(())
    /// # }
    /// ```
    pub fn new(vb: &VertexBuffer, ib: &IndexBuffer, app: Option<&Appearance>) -> Mesh {
        Mesh(Inner::new(
            Kind::Mesh(MeshData {
                vb: vb.clone(),
                ibs: vec![ib.clone()],
                apps: vec![app.cloned()],
                ext: Default::default(),
            }),
            true,
            true,
        ))
    }

    /// `Mesh(vertices, triangles[], appearances[])`: IllegalArgument if `ibs` is empty or
    /// `apps` is given and shorter than `ibs`.
    pub fn with_submeshes(
        vb: &VertexBuffer,
        ibs: &[IndexBuffer],
        apps: Option<&[Option<Appearance>]>,
    ) -> Result<Mesh> {
        if ibs.is_empty() {
            return iae("a mesh needs at least one submesh");
        }
        let apps = match apps {
            Some(a) if a.len() < ibs.len() => return iae("fewer appearances than submeshes"),
            Some(a) => a[..ibs.len()].to_vec(),
            None => vec![None; ibs.len()],
        };
        Ok(Mesh(Inner::new(
            Kind::Mesh(MeshData {
                vb: vb.clone(),
                ibs: ibs.to_vec(),
                apps,
                ext: Default::default(),
            }),
            true,
            true,
        )))
    }

    /// `setAppearance(index, appearance)`: IndexOutOfBounds for a bad submesh.
    pub fn set_appearance(&self, index: usize, app: Option<&Appearance>) -> Result<()> {
        let mut d = self.dm();
        match d.apps.get_mut(index) {
            Some(a) => {
                *a = app.cloned();
                Ok(())
            }
            None => ioobe("submesh index"),
        }
    }
    /// `getAppearance(index)`: IndexOutOfBounds for a bad submesh.
    pub fn appearance(&self, index: usize) -> Result<Option<Appearance>> {
        match self.d().apps.get(index) {
            Some(a) => Ok(a.clone()),
            None => ioobe("submesh index"),
        }
    }
    /// `getIndexBuffer(index)`: IndexOutOfBounds for a bad submesh.
    pub fn index_buffer(&self, index: usize) -> Result<IndexBuffer> {
        match self.d().ibs.get(index) {
            Some(i) => Ok(i.clone()),
            None => ioobe("submesh index"),
        }
    }
    /// `getVertexBuffer()`.
    pub fn vertex_buffer(&self) -> VertexBuffer {
        self.d().vb.clone()
    }
    /// `getSubmeshCount()`.
    pub fn submesh_count(&self) -> usize {
        self.d().ibs.len()
    }
}

#[derive(Clone, Debug)]
pub(crate) struct SpriteData {
    pub scaled: bool,
    pub image: Image2D,
    pub appearance: Option<Appearance>,
    pub crop: [i32; 4],
}

handle!(
    /// `Sprite3D`: a screen-aligned image at the node's origin, scaled or pixel-sized.
    Sprite3D,
    |i| matches!(i.kind, Kind::Sprite(_))
);
class_data!(Sprite3D, Sprite, SpriteData);
impl TransformableExt for Sprite3D {}
impl NodeExt for Sprite3D {}

fn full_crop(image: &Image2D) -> [i32; 4] {
    [
        0,
        0,
        image.width().min(MAX_SPRITE_CROP_DIMENSION),
        image.height().min(MAX_SPRITE_CROP_DIMENSION),
    ]
}

impl Sprite3D {
    /// `Sprite3D(scaled, image, appearance)`: the crop is the whole image (up to
    /// `maxSpriteCropDimension`).
    pub fn new(scaled: bool, image: &Image2D, app: Option<&Appearance>) -> Sprite3D {
        Sprite3D(Inner::new(
            Kind::Sprite(SpriteData {
                scaled,
                image: image.clone(),
                appearance: app.cloned(),
                crop: full_crop(image),
            }),
            true,
            true,
        ))
    }
    /// `isScaled()`.
    pub fn is_scaled(&self) -> bool {
        self.d().scaled
    }
    /// `setAppearance(a)`: only its CompositingMode, Fog and layer are used.
    pub fn set_appearance(&self, app: Option<&Appearance>) {
        self.dm().appearance = app.cloned();
    }
    /// `getAppearance()`.
    pub fn appearance(&self) -> Option<Appearance> {
        self.d().appearance.clone()
    }
    /// `setImage(image)`: resets the crop to the whole image.
    pub fn set_image(&self, image: &Image2D) {
        let mut d = self.dm();
        d.crop = full_crop(image);
        d.image = image.clone();
    }
    /// `getImage()`.
    pub fn image(&self) -> Image2D {
        self.d().image.clone()
    }
    /// `setCrop(x, y, width, height)`: negative sizes mirror; IllegalArgument if |width| or
    /// |height| exceeds `maxSpriteCropDimension`.
    pub fn set_crop(&self, x: i32, y: i32, width: i32, height: i32) -> Result<()> {
        if width.unsigned_abs() > MAX_SPRITE_CROP_DIMENSION as u32
            || height.unsigned_abs() > MAX_SPRITE_CROP_DIMENSION as u32
        {
            return iae("crop larger than maxSpriteCropDimension");
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
