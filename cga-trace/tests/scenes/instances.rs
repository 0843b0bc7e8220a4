//! Instances: a named object copied under further motors renders as the object moved
//! directly (its own transform, then the instance's), chains compose, a template is drawn
//! only through its instances, and an instance's material replaces the object's.

use cga_trace::integrator::Window;
use cga_trace::{Aov, Film, Renderer, Scene};

fn parse(text: &str) -> Result<Scene, String> {
    Scene::parse(text, "scene.toml").map_err(|e| e.to_string())
}

fn render(scene: &Scene) -> Film {
    let c = &scene.camera;
    Renderer::new(scene).render_window(Aov::Shaded, Window::full(c.width, c.height), &|| {})
}

/// The largest difference of any channel of any pixel.
fn largest_difference(a: &Film, b: &Film) -> f64 {
    a.pixels.iter().zip(&b.pixels).flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs())).fold(0.0, f64::max)
}

const HEAD: &str = "[camera]\nposition = [0.0, -16.0, 7.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = 50.0\nwidth = 96\nheight = 72\n\
    [[lights]]\nposition = [-6.0, -8.0, 12.0]\n\
    [materials.gold]\ncolour = [0.9, 0.7, 0.2]\nks = 0.6\nq = 40.0\n\
    [[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, -2.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = { colour = [0.6, 0.6, 0.6], kr = 0.3 }\n";

/// An evolved surface turned about its own centre: what every copy shares.
const RING: &str = "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, -0.5], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n\
    c2 = { centre = [0.3, 0.0, 0.8], normal = [0.3, 0.0, 1.0], radius = 0.5 }\ncaps = true\n\
    material = { colour = [0.2, 0.5, 0.9], ks = 0.5, q = 30.0 }\n";

const OWN: &str = "{ rotate = { axis = [1.0, 0.0, 0.0], degrees = 25.0 } }";

const MOVES: [&str; 3] = [
    "{ translate = [-4.0, 0.0, 0.0] }",
    "{ rotate = { axis = [0.0, 0.0, 1.0], degrees = 90.0 } }, { translate = [0.0, 2.0, 0.5] }",
    "{ rotate = { axis = [0.0, 1.0, 0.0], degrees = -40.0 } }, { translate = [4.0, -1.0, 0.0] }",
];

#[test]
fn instances_render_as_the_object_moved_directly() {
    let mut instanced = format!("{HEAD}[[objects]]\nname = \"ring\"\ntemplate = true\ntransform = [{OWN}]\n{RING}");
    let mut direct = HEAD.to_string();
    for (k, moves) in MOVES.iter().enumerate() {
        instanced.push_str(&format!(
            "[[objects]]\ntype = \"instance\"\nof = \"ring\"\nname = \"copy {k}\"\ntransform = [{moves}]\n"
        ));
        direct.push_str(&format!("[[objects]]\nname = \"copy {k}\"\ntransform = [{OWN}, {moves}]\n{RING}"));
    }
    let (a, b) = (parse(&instanced).unwrap(), parse(&direct).unwrap());
    // Each copy is a surface and its two caps; the template itself is not drawn.
    assert_eq!((a.objects.len(), b.objects.len()), (1 + 3 * 3, 1 + 3 * 3));
    let difference = largest_difference(&render(&a), &render(&b));
    // The motors compose in another order of products: rounding only.
    assert!(difference < 1e-9, "{difference}");
}

#[test]
fn an_instance_of_an_instance_composes_both_motors() {
    let one = "{ translate = [2.0, 0.0, 0.0] }";
    let two = "{ rotate = { axis = [0.0, 0.0, 1.0], degrees = 120.0 } }";
    let chained = format!(
        "{HEAD}[[objects]]\nname = \"ring\"\ntemplate = true\n{RING}\
         [[objects]]\ntype = \"instance\"\nof = \"ring\"\nname = \"moved\"\ntransform = [{one}]\n\
         [[objects]]\ntype = \"instance\"\nof = \"moved\"\ntransform = [{two}]\n"
    );
    let direct = format!(
        "{HEAD}[[objects]]\nname = \"moved\"\ntransform = [{one}]\n{RING}[[objects]]\ntransform = [{one}, {two}]\n{RING}"
    );
    let difference = largest_difference(&render(&parse(&chained).unwrap()), &render(&parse(&direct).unwrap()));
    assert!(difference < 1e-9, "{difference}");
}

#[test]
fn an_instances_material_and_name_replace_the_objects() {
    let text = format!(
        "{HEAD}[[objects]]\nname = \"ball\"\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmaterial = {{ colour = [1.0, 0.0, 0.0] }}\n\
         [[objects]]\ntype = \"instance\"\nof = \"ball\"\nname = \"gold ball\"\nmaterial = \"gold\"\ntransform = [{{ translate = [3.0, 0.0, 0.0] }}]\n"
    );
    let scene = parse(&text).unwrap();
    let (original, copy) = (&scene.objects[1], &scene.objects[2]);
    assert_eq!((&*original.name, &*copy.name), ("ball", "gold ball"));
    assert_eq!((original.material.colour, copy.material.colour), ([1.0, 0.0, 0.0], [0.9, 0.7, 0.2]));
}

#[test]
fn an_instance_of_an_instance_wears_the_nearest_material_and_only_its_own_label() {
    let text = format!(
        "{HEAD}[[objects]]\nname = \"ball\"\nlabel = \"the ball\"\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmaterial = {{ colour = [1.0, 0.0, 0.0] }}\n\
         [[objects]]\ntype = \"instance\"\nof = \"ball\"\nname = \"gold ball\"\nmaterial = \"gold\"\ntransform = [{{ translate = [3.0, 0.0, 0.0] }}]\n\
         [[objects]]\ntype = \"instance\"\nof = \"gold ball\"\nname = \"moved\"\nlabel = \"a copy\"\ntransform = [{{ translate = [0.0, 3.0, 0.0] }}]\n"
    );
    let scene = parse(&text).unwrap();
    let colours: Vec<[f64; 3]> = scene.objects[1..].iter().map(|o| o.material.colour).collect();
    assert_eq!(colours, [[1.0, 0.0, 0.0], [0.9, 0.7, 0.2], [0.9, 0.7, 0.2]]);
    // A label names one thing: the copy without its own has none.
    let labels: Vec<&str> = scene.labels.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(labels, ["the ball", "a copy"]);
}

#[test]
fn an_instances_own_label_is_reported_where_the_instance_gives_it() {
    // The plane is unbounded: a label on its copy is refused at the copy's `label` line, even
    // where the copied object's text is shorter or holds characters of several bytes there.
    let plane = "[[objects]]\nname = \"ground ✓✓✓\"\ntype = \"plane\"\npoint = [0.0, 0.0, -3.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = \"gold\"\n";
    let copy = "[[objects]]\ntype = \"instance\"\nof = \"ground ✓✓✓\"\nname = \"second ground, further down the scene\"\ntransform = [{ translate = [0.0, 0.0, -1.0] }]\nlabel = \"ground\"\n";
    let e = parse(&format!("{HEAD}{plane}{copy}")).unwrap_err();
    let line = HEAD.lines().count() + plane.lines().count() + 6;
    assert!(e.starts_with(&format!("scene.toml:{line}:")) && e.contains("label"), "{e}");
}

#[test]
fn instances_name_earlier_objects_and_errors_say_where() {
    let ball = "[[objects]]\nname = \"ball\"\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmaterial = { colour = [1.0, 0.0, 0.0] }\n";
    let copy = |of: &str, extra: &str| format!("[[objects]]\ntype = \"instance\"\nof = \"{of}\"\n{extra}");
    let head_lines = HEAD.lines().count();
    for (text, line, says) in [
        // Named only after the instance.
        (format!("{HEAD}{}{ball}", copy("ball", "")), head_lines + 3, "no object named `ball` before this one"),
        (format!("{HEAD}{ball}{}", copy("bal", "")), head_lines + 9, "no object named `bal`"),
        (format!("{HEAD}{ball}{}", copy("ball", "radius = 2.0\n")), head_lines + 10, "unknown field `radius`"),
        (format!("{HEAD}{ball}{}", copy("ball", "material = \"silver\"\n")), head_lines + 10, "no material `silver`"),
        (
            format!("{HEAD}{ball}{}", copy("ball", "motor = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\n")),
            head_lines + 10,
            "motor",
        ),
    ] {
        let e = parse(&text).unwrap_err();
        assert!(e.starts_with(&format!("scene.toml:{line}:")) && e.contains(says), "{e}");
    }
    // A template's own error is reported at its field, when an instance builds it.
    let bad = ball.replace("radius = 1.0", "radius = -1.0").replace("type =", "template = true\ntype =");
    let e = parse(&format!("{HEAD}{bad}{}", copy("ball", ""))).unwrap_err();
    assert!(e.starts_with(&format!("scene.toml:{}:", head_lines + 6)) && e.contains("radius"), "{e}");
}
