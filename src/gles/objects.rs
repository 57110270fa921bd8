//! A share group's namespace of one kind of object: buffer objects (ES 1.1 §2.9), texture
//! objects (§3.7) or renderbuffers (`OES_framebuffer_object`).
//!
//! Names and objects are kept apart. A binding point holds a [`Binding`]: the name it was
//! bound with (what queries return) and a counted reference to the object. Deleting a name
//! frees the name at once, and the deleting context unbinds it; but another context of the
//! share group that still has the object bound keeps drawing from it, mapping it or
//! updating it until its last binding goes (the rule later GL versions state, and what
//! programs sharing objects between threads rely on). Without this, a buffer mapped in one
//! context and deleted in another would leave the first writing into freed memory.
//!
//! Orphaned objects (no name left) are freed by [`Names::sweep`], which every namespace
//! operation runs; a binding dropped with its context frees its object at the next one.
#![forbid(unsafe_code)]

use std::collections::HashMap;
use std::sync::Arc;

use super::types::GLuint;

/// A counted reference to one object: bindings hold it, and the object lives while any does.
#[derive(Clone, Debug)]
struct ObjectRef(Arc<u64>);

impl ObjectRef {
    fn id(&self) -> u64 {
        *self.0
    }
}

/// What a binding point holds: the name it was bound with (0: none) and, for a non-zero
/// name, the object itself.
#[derive(Clone, Debug, Default)]
pub struct Binding {
    pub name: GLuint,
    object: Option<ObjectRef>,
}

impl Binding {
    /// The binding of nothing (name 0).
    pub const NONE: Binding = Binding {
        name: 0,
        object: None,
    };

    pub fn is_none(&self) -> bool {
        self.object.is_none()
    }

    /// True when both hold the same object (whatever names they were bound with).
    pub fn same_object(&self, other: &Binding) -> bool {
        match (&self.object, &other.object) {
            (Some(a), Some(b)) => a.id() == b.id(),
            _ => false,
        }
    }
}

impl PartialEq for Binding {
    fn eq(&self, other: &Binding) -> bool {
        self.name == other.name
            && self.object.as_ref().map(ObjectRef::id) == other.object.as_ref().map(ObjectRef::id)
    }
}

impl Eq for Binding {}

struct Slot<T> {
    object: T,
    /// The namespace's own reference: the object is unreferenced when it is the only one.
    hold: ObjectRef,
}

/// Names of one kind of object, and the objects themselves.
pub struct Names<T> {
    /// Every name in use: `None` for a name generated but not yet bound.
    names: HashMap<GLuint, Option<ObjectRef>>,
    objects: HashMap<u64, Slot<T>>,
    /// Objects whose name was deleted while a binding may still hold them.
    orphans: Vec<u64>,
    next_name: GLuint,
    next_id: u64,
}

impl<T> Default for Names<T> {
    fn default() -> Self {
        Names {
            names: HashMap::new(),
            objects: HashMap::new(),
            orphans: Vec::new(),
            next_name: 0,
            next_id: 0,
        }
    }
}

impl<T> std::fmt::Debug for Names<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Names")
            .field("names", &self.names.len())
            .field("objects", &self.objects.len())
            .field("orphans", &self.orphans.len())
            .finish()
    }
}

impl<T> Names<T> {
    /// `glGen*`: a name no object or generated name uses.
    pub fn generate(&mut self) -> GLuint {
        self.sweep();
        loop {
            self.next_name = self.next_name.wrapping_add(1).max(1);
            if !self.names.contains_key(&self.next_name) {
                self.names.insert(self.next_name, None);
                return self.next_name;
            }
        }
    }

    /// `glBind*`: the binding of `name`, whose object `make` creates when the name is unused
    /// or only generated. Name 0 binds nothing.
    pub fn bind(&mut self, name: GLuint, make: impl FnOnce() -> T) -> Binding {
        self.sweep();
        if name == 0 {
            return Binding::NONE;
        }
        let slot = self.names.entry(name).or_insert(None);
        let object = match slot {
            Some(r) => r.clone(),
            None => {
                self.next_id += 1;
                let r = ObjectRef(Arc::new(self.next_id));
                self.objects.insert(
                    self.next_id,
                    Slot {
                        object: make(),
                        hold: r.clone(),
                    },
                );
                *slot = Some(r.clone());
                r
            }
        };
        Binding {
            name,
            object: Some(object),
        }
    }

    /// The object called `name`, if the name has one.
    pub fn named(&self, name: GLuint) -> Option<&T> {
        let id = self.names.get(&name)?.as_ref()?.id();
        self.objects.get(&id).map(|s| &s.object)
    }

    /// The object a binding holds (alive even when its name was deleted elsewhere).
    pub fn get(&self, b: &Binding) -> Option<&T> {
        self.objects
            .get(&b.object.as_ref()?.id())
            .map(|s| &s.object)
    }

    pub fn get_mut(&mut self, b: &Binding) -> Option<&mut T> {
        self.objects
            .get_mut(&b.object.as_ref()?.id())
            .map(|s| &mut s.object)
    }

    /// `glDelete*` of one name: the name is freed and the binding it had returned, so the
    /// caller can unbind it from its own binding points (and then [`sweep`](Self::sweep)).
    /// `None` for 0, unused names and names only generated (those are freed too).
    pub fn delete(&mut self, name: GLuint) -> Option<Binding> {
        if name == 0 {
            return None;
        }
        let object = self.names.remove(&name)??;
        self.orphans.push(object.id());
        Some(Binding {
            name,
            object: Some(object),
        })
    }

    /// Frees the orphaned objects no binding holds any more.
    pub fn sweep(&mut self) {
        let objects = &mut self.objects;
        self.orphans.retain(|id| {
            let held = objects
                .get(id)
                .is_some_and(|s| Arc::strong_count(&s.hold.0) > 1);
            if !held {
                objects.remove(id);
            }
            held
        });
    }

    /// How many objects are stored (named or still bound somewhere).
    #[cfg(test)]
    pub fn stored(&self) -> usize {
        self.objects.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deleted_objects_live_while_bound() {
        let mut n: Names<Vec<u8>> = Names::default();
        let name = n.generate();
        let here = n.bind(name, || vec![1, 2, 3]);
        let elsewhere = n.bind(name, Vec::new);
        assert!(here.same_object(&elsewhere));
        let deleted = n.delete(name).expect("named");
        assert!(deleted.same_object(&here));
        drop(deleted);
        drop(here);
        n.sweep();
        // The name is free, the object is not: `elsewhere` still binds it.
        assert!(n.named(name).is_none());
        assert_eq!(n.get(&elsewhere), Some(&vec![1, 2, 3]));
        // A new object under the reused name is another object.
        let again = n.bind(name, || vec![9]);
        assert!(!again.same_object(&elsewhere));
        assert_eq!(n.stored(), 2);
        drop(elsewhere);
        n.sweep();
        assert_eq!(n.stored(), 1);
        assert_eq!(n.get(&again), Some(&vec![9]));
    }

    #[test]
    fn generated_names_are_unique_and_skip_zero() {
        let mut n: Names<()> = Names::default();
        let a = n.generate();
        let b = n.generate();
        assert!(a != 0 && b != 0 && a != b);
        assert!(n.delete(a).is_none(), "a generated name has no object");
        assert!(n.bind(0, || ()).is_none());
        n.next_name = u32::MAX - 1;
        let c = n.generate();
        let d = n.generate();
        assert_eq!(c, u32::MAX);
        assert!(
            d != 0 && d != b && d != c,
            "wraps past 0 and skips names in use"
        );
    }
}
