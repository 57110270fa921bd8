//! `Debug` for the handles: the class, the user ID and the fields that tell objects apart.
//! Referenced objects are summarized (a count, a size), never printed: a scene graph can
//! nest deeper than any stack allows recursion, and shares objects freely.

use std::fmt;

use super::color::Color;
use super::object::{Inner, Kind, ObjRef};

/// Writes `r` as `Class { user_id: …, … }`.
pub(crate) fn fmt_object(r: &ObjRef, f: &mut fmt::Formatter<'_>) -> fmt::Result {
    let Ok(i) = r.try_borrow() else {
        // Formatting from inside a mutation of the same object (a panic message, say).
        return write!(f, "<object being modified>");
    };
    let mut s = f.debug_struct(i.class_name());
    s.field("user_id", &i.user_id);
    fields(&i, &mut s);
    if !i.tracks.is_empty() {
        s.field("animation_tracks", &i.tracks.len());
    }
    s.finish()
}

fn fields(i: &Inner, s: &mut fmt::DebugStruct<'_, '_>) {
    match &i.kind {
        Kind::Group(g) => {
            s.field("children", &g.children.len());
        }
        Kind::World(w) => {
            s.field("children", &w.group.children.len());
            s.field("active_camera", &w.camera.is_some());
            s.field("background", &w.background.is_some());
        }
        Kind::Camera(c) => {
            s.field("projection", &c.projection);
            if c.projection != super::Projection::Generic {
                s.field("params", &c.params);
            }
        }
        Kind::Light(l) => {
            s.field("mode", &l.mode);
            s.field("color", &Color(l.color));
            s.field("intensity", &l.intensity);
        }
        Kind::Mesh(m) => {
            s.field("vertices", &m.vb.d().vertex_count());
            s.field("submeshes", &m.ibs.len());
        }
        Kind::Sprite(p) => {
            s.field("scaled", &p.scaled);
            s.field("crop", &p.crop);
        }
        Kind::Appearance(a) => {
            s.field("layer", &a.layer);
            s.field("material", &a.material.is_some());
            s.field("textures", &a.textures.iter().flatten().count());
        }
        Kind::Background(b) => {
            s.field("color", &Color(b.color));
            s.field("image", &b.image.is_some());
        }
        Kind::CompositingMode(c) => {
            s.field("blending", &c.blending);
        }
        Kind::PolygonMode(p) => {
            s.field("culling", &p.culling);
            s.field("winding", &p.winding);
            s.field("shading", &p.shading);
        }
        Kind::Material(m) => {
            s.field("diffuse", &Color(m.diffuse));
            s.field("shininess", &m.shininess);
        }
        Kind::Fog(g) => {
            s.field("mode", &g.mode);
            s.field("color", &Color(g.color));
        }
        Kind::Texture2D(t) => {
            let img = t.image.d();
            s.field("image", &format_args!("{}x{}", img.width, img.height));
            s.field("blending", &t.blending);
        }
        Kind::Image2D(d) => {
            s.field("format", &d.format);
            s.field("size", &format_args!("{}x{}", d.width, d.height));
            s.field("mutable", &d.mutable);
        }
        Kind::VertexArray(v) => {
            s.field("vertices", &v.count);
            s.field("components", &v.comps);
            s.field("component_size", &v.size);
        }
        Kind::VertexBuffer(v) => {
            s.field("vertices", &v.vertex_count());
        }
        Kind::IndexBuffer(x) => {
            s.field("indices", &x.triangles.len());
        }
        Kind::KeyframeSequence(k) => {
            s.field("keyframes", &k.times.len());
            s.field("components", &k.comps);
            s.field("interpolation", &k.interpolation);
            s.field("duration", &k.duration);
        }
        Kind::AnimationController(c) => {
            s.field("weight", &c.weight);
            s.field("speed", &c.speed);
        }
        Kind::AnimationTrack(t) => {
            s.field("property", &t.property);
            s.field("controller", &t.controller.is_some());
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::prelude::*;

    #[test]
    fn shows_class_user_id_and_key_fields() {
        let camera = Camera::new();
        camera.set_user_id(5);
        camera.set_perspective(60.0, 1.0, 1.0, 10.0).unwrap();
        assert_eq!(
            format!("{camera:?}"),
            "Camera { user_id: 5, projection: Perspective, params: [60.0, 1.0, 1.0, 10.0] }"
        );
        let light = Light::new();
        assert_eq!(
            format!("{light:?}"),
            "Light { user_id: 0, mode: Directional, color: Color(0x00FFFFFF), intensity: 1.0 }"
        );
        let image = Image2D::new(ImageFormat::Rgba, 4, 2).unwrap();
        assert_eq!(
            format!("{:?}", image.as_object3d()),
            "Image2D { user_id: 0, format: Rgba, size: 4x2, mutable: true }"
        );
    }

    #[test]
    fn groups_print_child_counts_not_children() {
        let world = World::new();
        let group = Group::new();
        group.add_child(&Group::new()).unwrap();
        world.add_child(&group).unwrap();
        assert_eq!(
            format!("{world:?}"),
            "World { user_id: 0, children: 1, active_camera: false, background: false }"
        );
        assert_eq!(format!("{group:?}"), "Group { user_id: 0, children: 1 }");
    }
}
