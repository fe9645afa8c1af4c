//! `save_new`: never overwrites, writes atomically, cleans up, and explains
//! every refusal; what it writes loads back bit for bit.

mod common;

use common::files_in;
use std::path::Path;
use std::time::{Duration, UNIX_EPOCH};

use roughtui::presets;
use roughtui::scene::State;
use roughtui::snapshot::{default_stem, load_file, save_new};

fn fig(n: &str) -> State {
    presets::load(n).unwrap()
}

/// fig2's parameters as a plain hand-made snapshot: 20 nm, the exact model,
/// no caption and the default moments.
fn plain() -> State {
    let mut s = fig("fig2");
    s.params = s.params.with(rough_model::Axis::HRms, 2e-8).unwrap();
    s.model = rough_model::Model::Exact;
    s.moments = rough_model::Moments::Truncated;
    s.caption = None;
    s
}

#[test]
fn two_saves_in_the_same_second_give_two_files() {
    let dir = tempfile::tempdir().unwrap();
    let t = UNIX_EPOCH + Duration::from_secs(1_795_275_012);
    let stem = default_stem("fig2", t);
    let a = save_new(dir.path(), &stem, &fig("fig2")).unwrap();
    let b = save_new(dir.path(), &stem, &fig("fig3")).unwrap();
    assert_eq!(a, dir.path().join("fig2-20261121-153012.ron"));
    assert_eq!(b, dir.path().join("fig2-20261121-153012-2.ron"));
    assert_eq!(
        files_in(dir.path()),
        ["fig2-20261121-153012-2.ron", "fig2-20261121-153012.ron"]
    );
    assert_eq!(load_file(&a).unwrap(), fig("fig2"));
    assert_eq!(load_file(&b).unwrap(), fig("fig3"));
}

#[test]
fn an_existing_file_is_never_overwritten() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("mine.ron"), "precious").unwrap();
    std::fs::write(dir.path().join("mine-2.ron"), "also precious").unwrap();
    std::fs::create_dir(dir.path().join("mine-3.ron")).unwrap();
    let p = save_new(dir.path(), "mine", &fig("fig1")).unwrap();
    assert_eq!(p, dir.path().join("mine-4.ron"));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("mine.ron")).unwrap(),
        "precious"
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("mine-2.ron")).unwrap(),
        "also precious"
    );
    assert_eq!(load_file(&p).unwrap(), fig("fig1"));
}

#[test]
fn concurrent_saves_of_one_name_all_land_intact() {
    let dir = tempfile::tempdir().unwrap();
    let states: Vec<State> = ["fig1", "fig2", "fig3", "fig4"]
        .iter()
        .map(|n| fig(n))
        .collect();
    let paths: Vec<_> = std::thread::scope(|s| {
        let hs: Vec<_> = (0..8)
            .map(|i| {
                let (d, st) = (dir.path(), &states[i % 4]);
                s.spawn(move || (save_new(d, "class", st).unwrap(), i % 4))
            })
            .collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert_eq!(files_in(dir.path()).len(), 8, "{:?}", files_in(dir.path()));
    for (p, i) in paths {
        assert_eq!(load_file(&p).unwrap(), states[i], "{}", p.display());
    }
}

#[test]
fn the_saved_text_is_schema_v1() {
    let dir = tempfile::tempdir().unwrap();
    let p = save_new(dir.path(), "fig2", &plain()).unwrap();
    assert_eq!(
        std::fs::read_to_string(p).unwrap(),
        "(\n    version: 1,\n    name: \"fig2\",\n    params: (h0_over_e: 0.01, h_rms: 2e-8, \
         zeta: 128.0, hurst: 0.8, r_star: 0.001, q0: 100000.0),\n    size_effect: false,\n    \
         sweep: (axis: Zeta, from: 1.0, to: 10000.0),\n    model: Exact,\n)\n"
    );
}

#[test]
fn optional_fields_are_written_only_when_set() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = plain();
    s.caption = Some("Figure 2: \"slopes\" against ζ".into());
    s.moments = rough_model::Moments::Asymptotic;
    let p = save_new(dir.path(), "fig2", &s).unwrap();
    assert_eq!(
        std::fs::read_to_string(&p).unwrap(),
        "(\n    version: 1,\n    name: \"fig2\",\n    caption: \"Figure 2: \\\"slopes\\\" against ζ\",\n    \
         params: (h0_over_e: 0.01, h_rms: 2e-8, zeta: 128.0, hurst: 0.8, r_star: 0.001, q0: 100000.0),\n    \
         size_effect: false,\n    sweep: (axis: Zeta, from: 1.0, to: 10000.0),\n    model: Exact,\n    \
         moments: Asymptotic,\n)\n"
    );
    assert_eq!(load_file(&p).unwrap(), s);
}

#[test]
fn read_only_folder_is_an_error_naming_the_folder() {
    use std::os::unix::fs::PermissionsExt;
    let tmp = tempfile::tempdir().unwrap();
    let ro = tmp.path().join("ro");
    std::fs::create_dir(&ro).unwrap();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    // Root ignores permissions; /sys refuses new files even to root.
    let dir = if std::fs::File::create(ro.join("probe")).is_ok() {
        std::fs::remove_file(ro.join("probe")).unwrap();
        Path::new("/sys").to_path_buf()
    } else {
        ro.clone()
    };
    let before = files_in(&dir);
    let e = save_new(&dir, "fig2", &fig("fig2"))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with(&format!("cannot save snapshot in {}: ", dir.display())),
        "{e}"
    );
    assert!(
        e.contains("Permission denied") || e.contains("Read-only file system"),
        "{e}"
    );
    assert_eq!(files_in(&dir), before);
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
}

#[test]
fn missing_folder_is_an_error_naming_it() {
    let tmp = tempfile::tempdir().unwrap();
    let gone = tmp.path().join("gone");
    let e = save_new(&gone, "x", &fig("fig2")).unwrap_err().to_string();
    assert_eq!(
        e,
        format!(
            "cannot save snapshot in {}: No such file or directory (os error 2)",
            gone.display()
        )
    );
}

#[test]
fn bad_stems_are_refused_clearly() {
    let dir = tempfile::tempdir().unwrap();
    for (stem, why) in [
        ("", "\"\": it is empty"),
        ("   ", "\"   \": it is empty"),
        (".ron", "\".ron\": it is empty"),
        (
            "a/b",
            "\"a/b\": it must be a file name, not a path (no '/' or '\\')",
        ),
        (
            "../up",
            "\"../up\": it must be a file name, not a path (no '/' or '\\')",
        ),
        ("..", "\"..\": it must not start with '.'"),
        (".", "\".\": it must not start with '.'"),
        (".hidden", "\".hidden\": it must not start with '.'"),
        (
            "nul\0byte",
            "\"nul\\0byte\": it contains a control character",
        ),
        (
            "tab\there",
            "\"tab\\there\": it contains a control character",
        ),
    ] {
        let e = save_new(dir.path(), stem, &fig("fig2"))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            format!("cannot save snapshot: bad file name {why}"),
            "{stem:?}"
        );
    }
    let long = "x".repeat(201);
    let e = save_new(dir.path(), &long, &fig("fig2"))
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        format!("cannot save snapshot: bad file name {long:?}: it is 201 bytes long: at most 200")
    );
    assert_eq!(files_in(dir.path()), Vec::<String>::new());
}

#[test]
fn typed_names_are_tidied() {
    let dir = tempfile::tempdir().unwrap();
    assert_eq!(
        save_new(dir.path(), "  lab 3.ron ", &fig("fig2")).unwrap(),
        dir.path().join("lab 3.ron")
    );
    assert_eq!(
        save_new(dir.path(), &"y".repeat(200), &fig("fig2")).unwrap(),
        dir.path().join(format!("{}.ron", "y".repeat(200)))
    );
}

#[test]
fn default_stems_are_safe_file_names() {
    let t = UNIX_EPOCH + Duration::from_secs(1_795_275_012);
    assert_eq!(default_stem("fig2", t), "fig2-20261121-153012");
    assert_eq!(default_stem("a/b c", t), "a_b_c-20261121-153012");
    assert_eq!(default_stem("../etc", t), "_etc-20261121-153012");
    assert_eq!(default_stem("", t), "snapshot-20261121-153012");
    assert_eq!(default_stem("Ψ*", t), "Ψ_-20261121-153012");
    assert_eq!(default_stem("x", UNIX_EPOCH), "x-19700101-000000");
    assert_eq!(
        default_stem("x", UNIX_EPOCH + Duration::from_secs(951_782_400)),
        "x-20000229-000000"
    );
    assert_eq!(
        default_stem("x", UNIX_EPOCH - Duration::from_secs(10)),
        "x-19700101-000000"
    );
}

#[test]
fn a_state_that_could_not_be_loaded_back_is_not_saved() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = fig("fig2");
    s.name = "line\nbreak".into();
    assert_eq!(
        save_new(dir.path(), "x", &s).unwrap_err().to_string(),
        "cannot save snapshot: name contains the control character U+000A: it must be printable text"
    );
    let mut s = plain();
    s.caption = Some("x".repeat(301));
    assert_eq!(
        save_new(dir.path(), "x", &s).unwrap_err().to_string(),
        "cannot save snapshot: caption is 301 characters long: it must be at most 300"
    );
    let mut s = fig("fig2");
    s.params = s.params.with(rough_model::Axis::Hurst, 1.0).unwrap();
    s.moments = rough_model::Moments::Asymptotic;
    assert!(save_new(dir.path(), "x", &s)
        .unwrap_err()
        .to_string()
        .starts_with("cannot save snapshot: hurst = 1 needs moments: Truncated"));
    assert_eq!(files_in(dir.path()), Vec::<String>::new());
}
