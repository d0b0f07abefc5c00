use super::*;

fn base() -> Scene {
    SceneFile::from_toml(
        "pattern = 'square-tri'\n[slider]\nradius_um = 20\n[substrate]\nsize_um = [80, 80]\n",
        "base",
    )
    .unwrap()
    .into_scene()
    .unwrap()
}

fn vary(text: &str) -> Vary {
    parse_vary(text, "--vary").unwrap()
}

#[test]
fn a_varied_field_is_the_scene_file_written_with_that_value() {
    let r = variants(
        &base(),
        "b",
        &[
            vary("slider.sphere_diameter_um=2,2.5"),
            vary("slider.material.youngs_GPa=50"),
        ],
        Fairness::Area,
        false,
        "--vary",
    )
    .unwrap();
    assert_eq!(r.variants.len(), 2);
    assert_eq!(
        r.variants[1].name,
        "b+slider.sphere_diameter_um=2.5+slider.material.youngs_GPa=50"
    );
    let written = SceneFile::from_toml(
        "pattern = 'square-tri'\n[slider]\nradius_um = 20\nsphere_diameter_um = 2.5\n[slider.material]\nyoungs_GPa = 50\n[substrate]\nsize_um = [80, 80]\n",
        "w",
    )
    .unwrap()
    .into_scene()
    .unwrap();
    assert_eq!(r.variants[1].scene, written);
    // a lattice field: the preset's lattice is written out to be changed
    let r = variants(
        &base(),
        "b",
        &[vary("slider.lattice.spacing_um=3:4:0.5")],
        Fairness::Area,
        false,
        "--vary",
    )
    .unwrap();
    assert_eq!(r.variants.len(), 3);
    assert_eq!(r.variants[2].scene.slider.lattice.a1[0], 4e-6);
    // equal area by default: the outline is the base's
    assert!(r
        .variants
        .iter()
        .all(|v| v.scene.slider.radius == base().slider.radius));
}

#[test]
fn equal_count_scales_the_outline() {
    let b = base();
    let n = b.slider_sites_local().len();
    let r = variants(
        &b,
        "b",
        &[vary("slider.lattice.spacing_um=3.5")],
        Fairness::Count,
        false,
        "--vary",
    )
    .unwrap();
    let v = &r.variants[0].scene;
    let m = v.slider_sites_local().len();
    assert!((m as f64 / n as f64 - 1.0).abs() < 0.05, "{m} vs {n}");
    assert!(v.slider.radius > 20e-6);
    let e = variants(
        &b,
        "b",
        &[vary("slider.radius_um=10")],
        Fairness::Count,
        false,
        "--vary",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("slider.radius_um"), "{e}");
}

#[test]
fn recipes_that_cannot_be_made_are_named_or_skipped() {
    // 3.5 µm spheres on the 3 µm lattice overlap
    let e = variants(
        &base(),
        "b",
        &[vary("slider.sphere_diameter_um=2.5,3.5")],
        Fairness::Area,
        false,
        "--vary",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("--vary")
            && e.contains("slider.sphere_diameter_um = 3.5")
            && e.contains("slider.lattice"),
        "{e}"
    );
    let r = variants(
        &base(),
        "b",
        &[vary("slider.sphere_diameter_um=2.5,3.5")],
        Fairness::Area,
        true,
        "--vary",
    )
    .unwrap();
    assert_eq!((r.variants.len(), r.skipped.len()), (1, 1));
    // a pad beyond the substrate
    let e = variants(
        &base(),
        "b",
        &[vary("slider.radius_um=50")],
        Fairness::Area,
        false,
        "--vary",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("slider.radius_um") && e.contains("does not fit"),
        "{e}"
    );
}

#[test]
fn bad_input_names_the_flag_and_field() {
    for (text, want) in [
        ("slider.sphere_diameter_um", "FIELD=LIST"),
        ("slider.sphere_diameter_um=", "empty"),
        ("slider.sphere_diameter_um=a,b", "not a number"),
        ("=1,2", "dotted scene field"),
    ] {
        let e = parse_vary(text, "--vary").unwrap_err().to_string();
        assert!(e.contains("--vary") && e.contains(want), "{text}: {e}");
    }
    for (field, want) in [
        ("slider.diameter_um=2", "diameter_um"),
        ("slider.tilt=1", "slider.tilt"),
        ("slider.radius_um.x=1", "slider.radius_um"),
    ] {
        let e = variants(
            &base(),
            "b",
            &[vary(field)],
            Fairness::Area,
            false,
            "--vary",
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("--vary") && e.contains(want), "{field}: {e}");
    }
    // an integer field takes whole numbers
    let r = variants(
        &base(),
        "b",
        &[vary("substrate.seed=2,3")],
        Fairness::Area,
        false,
        "--vary",
    )
    .unwrap();
    assert_eq!(r.variants[1].scene.substrate.seed, 3);
}

#[test]
fn the_validated_range_is_the_studys() {
    assert!(outside_validated_range(&base()).is_none());
    let r = variants(
        &base(),
        "b",
        &[vary("slider.material.youngs_GPa=50")],
        Fairness::Area,
        false,
        "--vary",
    )
    .unwrap();
    let why = outside_validated_range(&r.variants[0].scene).unwrap();
    assert!(why.contains("slider E = 50 GPa"), "{why}");
}
