use GLES_CM::m3g::*;
fn main() {
    let l = loader::Loader::new().load_file(std::env::args().nth(1).unwrap()).unwrap();
    for (i, o) in l.objects.iter().enumerate() {
        if let Some(c) = o.downcast::<AnimationController>() {
            println!("{} ctl speed {} weight {} [{},{}) pos(0)={} pos(1000)={}", i+2, c.speed(), c.weight(), c.active_interval_start(), c.active_interval_end(), c.position(0), c.position(1000));
        }
        if let Some(k) = o.downcast::<KeyframeSequence>() {
            if k.component_count() == 4 { for i in 0..k.keyframe_count() { print!(" {:?}", k.get_keyframe(i).unwrap()); } println!(); }
            println!("{} kf n={} c={} interp={} dur={} rep={} range {}..{} k0={:?} klast={:?}", i+2, k.keyframe_count(), k.component_count(), k.interpolation_type(), k.duration(), k.repeat_mode(), k.valid_range_first(), k.valid_range_last(), k.get_keyframe(0).unwrap(), k.get_keyframe(k.keyframe_count()-1).unwrap());
        }
        if let Some(t) = o.downcast::<AnimationTrack>() {
            println!("{} track prop {} ctl {}", i+2, t.target_property(), t.controller().is_some());
        }
        if o.animation_track_count() > 0 { println!("{} {} has {} tracks", i+2, o.class_name(), o.animation_track_count()); }
    }
    let w = l.roots.iter().find_map(|r| r.downcast::<World>()).unwrap();
    for t in [0, 1000, 2500] {
        let v = w.animate(t);
        let g = l.objects[14].downcast::<Group>().unwrap();
        for o in &l.objects { if let Some(sm) = o.downcast::<SkinnedMesh>() { let (p, _) = sm.skinned_vertices().unwrap(); println!("skinned v0 {:?} v100 {:?}", p[0], p[100]); let (_, sb) = sm.skinned_vertex_buffer().unwrap().get_positions(); println!("svb {:?}", sb); } }
        println!("t={t} animate={v:?} obj18 translation {:?} orient {:?}", g.get_translation(), g.get_orientation());
    }
}
#[allow(dead_code)]
fn unused() {}
