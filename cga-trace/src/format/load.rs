//! Loading: a scene file, its includes, images and meshes read once ([`Source`]), checked
//! and placed at any time of its motion into a [`Scene`].

use super::error::{SceneError, line_column_bytes, printable};
use super::include::{self, Joined};
use super::instance::{InstanceSpec, is_instance, is_template, moves, name_of};
use super::objects::{ObjectSpec, build_object};
use super::{Assets, SceneFile, sections};
use crate::drawing::Marks;
use crate::frame::Frame;
use crate::invalid::Invalid;
use crate::label::Label;
use crate::light::Light;
use crate::limits::{MAX_DOCUMENT_TOKENS, MAX_FILE_BYTES, MAX_LIGHTS, MAX_MATERIALS, MAX_OBJECTS, MAX_SHADOW_RAYS};
use crate::object::Object;
use crate::scene::Scene;
use crate::settings::Settings;
use crate::surface::Method;
use cga_core::Motor;
use cga_core::euclid::E3;
use serde::Deserialize;
use serde::de::IntoDeserializer;
use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;
impl Scene {
    /// Read and check a scene file of at most [`MAX_FILE_BYTES`], at the start of its
    /// motion, its camera's size its own (a [`Pipeline`](crate::Pipeline) places a scene at
    /// any time, with any size and settings: [`View`](crate::View)).
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        Source::load(path)?.scene(None, 0.0)
    }

    /// Check a scene given as text; `file` names it in errors, and its folder is where the
    /// files it names are read from.
    ///
    /// Memory is bounded per object: the file is cut at its table headers, each
    /// `[[objects]]` section parsed, placed and built alone and dropped before the next
    /// (`format/sections.rs`), so loading holds the file, one object's parsed form and
    /// the scene built so far (about 225 bytes an object).
    pub fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
        Source::parse(text, file)?.scene(None, 0.0)
    }
}

/// A scene file and every file it reads, read once: the text with its includes joined, and
/// the images and meshes it names, each decoded once. [`Source::scene`] places it at any
/// time of its motion without reading a file again, as a shutter's instants and an
/// animation's frames need.
pub struct Source {
    joined: Joined,
    assets: Assets,
    /// The scene file's name, for errors.
    file: String,
    /// Each object that does not move, as last built: a shutter's instants and an
    /// animation's frames place only the objects that move.
    still: HashMap<usize, Still>,
    /// How many times the scene has been placed: what stands is kept from the second time
    /// (a scene placed once, as for one still picture, keeps nothing).
    placed: usize,
}

/// An object without `motion` (nor any along its instances' chain), kept between the times
/// a [`Source`] is placed at: its extent, and the object as built in a frame with marks.
#[derive(Default)]
struct Still {
    extent: Option<(Option<(E3, f64)>, usize)>,
    built: Option<(Placing, Vec<Object>, Option<Label>)>,
}

/// What an object's build depends on besides its own table: the frame it is given in, the
/// surfaces' method and, for a drawing, the marks (sized by the whole scene, moving
/// objects included).
#[derive(Clone, Copy, PartialEq)]
struct Placing {
    frame: ([u64; 3], u64),
    method: Method,
    marks: Option<Marks>,
}

impl Placing {
    /// This placing for an object that draws (`true`: the marks count) or not.
    fn of(self, draws: bool) -> Placing {
        Placing { marks: self.marks.filter(|_| draws), ..self }
    }
}

impl Source {
    /// Read the scene file `path` (at most [`MAX_FILE_BYTES`]) and the files it includes.
    pub fn load(path: &Path) -> Result<Source, SceneError> {
        use std::io::Read;
        let file = path.display().to_string();
        let io = |source| SceneError::Io { file: file.clone(), source };
        let mut bytes = Vec::new();
        std::fs::File::open(path).and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes)).map_err(io)?;
        if bytes.len() as u64 > MAX_FILE_BYTES {
            let message = format!("the file is larger than the limit of {MAX_FILE_BYTES} bytes");
            return Err(SceneError::Syntax { file, line: 1, column: 1, message });
        }
        let text = String::from_utf8(bytes).map_err(|e| {
            let (line, column) = line_column_bytes(e.as_bytes(), e.utf8_error().valid_up_to());
            SceneError::Syntax { file: file.clone(), line, column, message: "the file is not UTF-8 text".into() }
        })?;
        Source::parse(&text, &file)
    }

    /// A scene given as text (`file` names it in errors, and its folder is where the files
    /// it names are read from), with the files it includes.
    pub fn parse(text: &str, file: &str) -> Result<Source, SceneError> {
        let joined = include::join(text, file)?;
        let folder = Path::new(file).parent().unwrap_or(Path::new(""));
        Ok(Source {
            joined,
            assets: crate::format::Assets::new(folder),
            file: file.into(),
            still: HashMap::new(),
            placed: 0,
        })
    }

    /// The scene at the frame time `time` in [0, 1] (clamped; NaN is the start), with `size`
    /// (width, height) for a camera that gives neither: objects and the camera with a
    /// `motion` placed by their keyframes' screw motion at that time. Images and meshes are
    /// read the first time they are needed and kept for every later time.
    pub fn scene(&mut self, size: Option<(u32, u32)>, time: f64) -> Result<Scene, SceneError> {
        let (joined, assets, file, still) = (&self.joined, &mut self.assets, self.file.as_str(), &mut self.still);
        let again = self.placed > 0;
        self.placed += 1;
        // NaN is no time: the start.
        let time = if time.is_nan() { 0.0 } else { time.clamp(0.0, 1.0) };
        let text = joined.text.as_str();
        let at = |offset: usize| joined.locate(offset);
        let mut sections = sections::split(text).map_err(|m| {
            let (file, line, column) = at(m.at);
            SceneError::Syntax { file, line, column, message: m.message }
        })?;
        joined.reading_order(&mut sections.objects);
        let tokens = sections::significant_tokens(&sections.rest);
        if let (Some(open), true) = (sections.unclosed, tokens > MAX_DOCUMENT_TOKENS) {
            let (file, line, column) = at(open);
            let message = "this bracket is never closed: the rest of the file is read as inside it".into();
            return Err(SceneError::Syntax { file, line, column, message });
        }
        if tokens > MAX_DOCUMENT_TOKENS {
            let message = format!(
                "the file outside its `[[objects]]` tables holds {tokens} values, keys and brackets, more than the {MAX_DOCUMENT_TOKENS} read at once (objects written as `objects = [ … ]` count here: write them as `[[objects]]` tables, which are read one at a time)"
            );
            return Err(SceneError::Syntax { file: file.into(), line: 1, column: 1, message });
        }
        // Offsets in the rest of the file are mapped back to the file; an object's count from
        // its section's start.
        let rest = |offset: usize| sections.file_offset(offset);
        let invalid = |map: &dyn Fn(usize) -> usize, span: Range<usize>, what: String, reason: Invalid| {
            let (file, line, column) = at(map(reason.span().unwrap_or(span).start));
            SceneError::Invalid { file, line, column, what, reason }
        };
        let mut document = toml::de::DeTable::parse(&sections.rest).map_err(|e| syntax_error(joined, &e, &rest))?;
        // `objects = [ … ]` written as one array in the root, instead of `[[objects]]` tables.
        let inline = match document.get_mut().remove_entry("objects") {
            None => toml::de::DeArray::new(),
            Some((_, value)) if matches!(value.get_ref(), toml::de::DeValue::Array(_)) => match value.into_inner() {
                toml::de::DeValue::Array(objects) => objects,
                _ => unreachable!("an array"),
            },
            // Not a list: put back, for the scene's own fields to say what is wrong with it.
            Some((key, value)) => {
                document.get_mut().insert(key, value);
                toml::de::DeArray::new()
            }
        };
        if let (Some(first), false) = (sections.objects.iter().min_by_key(|r| r.start), inline.is_empty()) {
            let (file, line, column) = at(first.start);
            let message = "duplicate key `objects`: given as an array and as `[[objects]]` tables".into();
            return Err(SceneError::Syntax { file, line, column, message });
        }
        let spec: SceneFile = SceneFile::deserialize(toml::de::Deserializer::from(document))
            .map_err(|e| syntax_error(joined, &e, &rest))?;
        let (settings, render_span) =
            spec.render.map_or((Settings::default(), 0..0), |r| (Settings::from(*r.get_ref()), r.span()));
        settings.check().map_err(|reason| invalid(&rest, render_span, "render".into(), reason))?;
        let count = inline.len().max(sections.objects.len());
        let limit = |what, found: usize, limit: usize| {
            (found > limit).then_some(Invalid::Limit { what, found: found as u64, limit: limit as u64 })
        };
        let too_many = limit("objects", count, MAX_OBJECTS)
            .or(limit("lights", spec.lights.len(), MAX_LIGHTS))
            .or(limit("materials", spec.materials.len(), MAX_MATERIALS));
        if let Some(e) = too_many {
            return Err(invalid(&|_| 0, 0..0, "scene".into(), e));
        }
        let camera_span = spec.camera.span();
        let in_camera = |reason| invalid(&rest, camera_span.clone(), "camera".into(), reason);
        let built = spec.camera.into_inner().build(size, time).map_err(in_camera)?;
        let (camera, position, pinned, shutter) = (built.camera, built.position, built.pinned, built.shutter);
        // Objects size the frame; lights do not (a light far away is only a direction). Each
        // object's placement is read first (a few of its fields), before any is built.
        // Object `k` as parsed, and where its spans count from.
        let start_of = |k: usize| sections.objects.get(k).map(|r| r.start);
        let map_of = |k: usize| move |offset: usize| start_of(k).map_or_else(|| rest(offset), |s| s + offset);
        let value_of = |k: usize| match sections.objects.get(k) {
            Some(range) => section_object(&text[range.clone()]).map_err(|e| syntax_error(joined, &e, &map_of(k))),
            None => Ok(inline[k].clone()),
        };
        // Each instance as placed: read in order, so that an instance names an object before it.
        let mut named: HashMap<String, Placed> = HashMap::new();
        let mut instances: HashMap<usize, Placed> = HashMap::new();
        let mut sizes = Vec::with_capacity(count);
        let mut templates = Vec::new();
        let mut shapes = 0;
        // Whether anything moves: only then is the scene placed again at other times with
        // the same objects, and what stands worth keeping.
        let mut anything_moves = false;
        for k in 0..count {
            let value = value_of(k)?;
            let placed = if is_instance(&value) {
                let (spec, span) = instance_spec(&value, &map_of(k), joined)?;
                let located = |reason| invalid(&map_of(k), span.clone(), format!("object {}", k + 1), reason);
                let of = named.get(spec.of.get_ref()).ok_or_else(|| {
                    let why = format!("no object named `{}` before this one", spec.of.get_ref().escape_debug());
                    located(Invalid::at("of", spec.of.span(), Invalid::Range(why)))
                })?;
                let motor = spec.motor(time).map_err(located)?;
                let placed = of.under(motor, spec.material.is_some().then_some(k), moves(&value));
                instances.insert(k, placed);
                placed
            } else {
                Placed { base: k, outer: None, material: None, moving: moves(&value) }
            };
            if let Some(name) = name_of(&value) {
                named.insert(name, placed);
            }
            if is_template(&value) {
                templates.extend(name_of(&value));
                continue;
            }
            let span = value.span();
            let kept = still.get(&k).and_then(|s| s.extent).filter(|_| !placed.moving);
            let (extent, triangles) = match kept {
                Some(kept) => kept,
                None => {
                    let base = if placed.base == k { value } else { value_of(placed.base)? };
                    let extent = ObjectSpec::extent_of(&base, time, placed.outer, assets);
                    extent.map_err(|e| syntax_error(joined, &e, &map_of(placed.base)))?
                }
            };
            anything_moves |= placed.moving;
            if placed.moving {
                still.remove(&k);
            } else {
                still.entry(k).or_default().extent = Some((extent, triangles));
            }
            sizes.extend(extent);
            // Meshes' triangles (each instance's too) counted before any is built.
            shapes += triangles;
            if let Some(e) = limit("shapes", shapes, MAX_OBJECTS) {
                return Err(invalid(&map_of(k), span, format!("object {}", k + 1), e));
            }
        }
        let pixel = camera.x_max / camera.focal / f64::from(camera.width);
        let marks = Marks::for_scene(&sizes, position, pixel);
        let frame = Frame::around(position, sizes, pixel)
            .map_err(|span| invalid(&|_| 0, 0..0, "scene".into(), Invalid::Range(span.to_string())))?;
        let camera = camera.with_lens(built.lens.in_frame(frame.scale)).map_err(|e| in_camera(e.into()))?;
        for (name, m) in spec.materials {
            let span = m.span();
            let what = format!("material `{}`", name.escape_debug());
            assets.insert(name, m.get_ref()).map_err(|reason| invalid(&rest, span, what, reason))?;
        }
        let environment = match &spec.environment {
            Some(e) => Some(
                e.get_ref().build(assets).map_err(|reason| invalid(&rest, e.span(), "environment".into(), reason))?,
            ),
            None => None,
        };
        let mut lights: Vec<Light> = Vec::with_capacity(spec.lights.len());
        let mut rays = 0;
        for (k, light) in spec.lights.into_iter().enumerate() {
            let span = light.span();
            let what = format!("light {}", k + 1);
            lights.push(light.into_inner().build(&frame).map_err(|reason| invalid(&rest, span.clone(), what, reason))?);
            // Every light casts a shadow ray at every hit, an area light one per sample.
            rays += u64::from(lights[k].samples().unwrap_or(1));
            if rays > MAX_SHADOW_RAYS {
                let reason = Invalid::Limit {
                    what: "shadow rays a hit (lights and their samples)",
                    found: rays,
                    limit: MAX_SHADOW_RAYS,
                };
                return Err(invalid(&rest, span, format!("light {}", k + 1), reason));
            }
        }
        let mut built = Vec::with_capacity(shapes.max(count));
        let mut labels = Vec::new();
        let placing = Placing {
            frame: (frame.origin.map(f64::to_bits), frame.scale.to_bits()),
            method: settings.surface_method,
            marks: Some(marks),
        };
        for k in 0..count {
            // An object that does not move, built in this frame already: as it was.
            if let Some(Still { built: Some((at, objects, label)), .. }) = still.get(&k)
                && *at == placing.of(at.marks.is_some())
            {
                built.extend(objects.iter().cloned());
                labels.extend(label.clone());
                continue;
            }
            let value = value_of(k)?;
            if is_template(&value) {
                continue;
            }
            // An instance is built from the object it copies, whose fields its errors name,
            // but for those the instance gives.
            let moving = instances.get(&k).map_or(moves(&value), |p| p.moving);
            let (j, span, dress) = match instances.get(&k) {
                Some(&placed) => {
                    let (instance, span) = instance_spec(&value, &map_of(k), joined)?;
                    // The material of the last instance in the chain that gives one.
                    let given = match placed.material {
                        Some(m) if m == k => Some((m, instance.material.clone(), span.clone())),
                        Some(m) => {
                            let (giver, giver_span) = instance_spec(&value_of(m)?, &map_of(m), joined)?;
                            Some((m, giver.material, giver_span))
                        }
                        None => None,
                    };
                    // Checked where it is given: the instance that gives it, at its own span.
                    if let Some((m, Some(material), giver_span)) = &given {
                        let what = format!("object {}", m + 1);
                        assets
                            .resolve(material)
                            .map_err(|reason| invalid(&map_of(*m), giver_span.clone(), what, reason))?;
                    }
                    let material = given.and_then(|(_, material, _)| material);
                    (placed.base, span, Some((instance, placed, material)))
                }
                None => (k, value.span(), None),
            };
            let base = if j == k { value } else { value_of(j)? };
            let mut spec = ObjectSpec::read(base).map_err(|e| syntax_error(joined, &e, &map_of(j)))?;
            // Where a field's span counts from: the object copied, or the instance giving it
            // (a copy carries only its own instance's label).
            let mut material_from = j;
            if let Some((instance, placed, material)) = dress {
                material_from = placed.material.unwrap_or(j);
                spec = instance.dress(spec, placed.outer, material);
            }
            let owner = |reason: &Invalid| match reason.field() {
                Some("label") => k,
                Some("material") => material_from,
                _ => j,
            };
            spec.time = time;
            let draws = spec.draws();
            let (object, name) = build_object(spec, k, settings.surface_method, &frame, &marks, assets);
            let what = format!("object `{name}`");
            // Errors at a field where that field is written; others at the object.
            let at = |reason: Invalid| match reason.span() {
                Some(_) => invalid(&map_of(owner(&reason)), span.clone(), what.clone(), reason),
                None => invalid(&map_of(k), span.clone(), what.clone(), reason),
            };
            let (mut objects, label) = object.map_err(at)?;
            // A drawing or a mesh is several shapes: all count against the limit.
            if let Some(e) = limit("shapes", built.len() + objects.len(), MAX_OBJECTS) {
                return Err(at(e));
            }
            if moving {
                objects.iter_mut().for_each(|o| o.moving = true);
            } else if anything_moves && again {
                still.entry(k).or_default().built = Some((placing.of(draws), objects.clone(), label.clone()));
            }
            built.extend(objects);
            labels.extend(label);
        }
        let mut inputs = joined.inputs();
        inputs.extend(assets.inputs());
        Ok(Scene {
            frame,
            camera,
            objects: built,
            lights,
            settings,
            labels,
            pinned,
            shutter,
            environment,
            inputs,
            templates,
        })
    }
}

/// Where an object comes from: the object copied (`base`, itself if not an instance), the
/// motor its instances put it under, the instance whose material it wears, if any, and
/// whether it moves (a `motion` anywhere along the chain).
#[derive(Clone, Copy)]
struct Placed {
    base: usize,
    outer: Option<Motor>,
    material: Option<usize>,
    moving: bool,
}

impl Placed {
    /// This placement under a further instance's `motor` (applied after), wearing the
    /// material of instance `material` where given; `moving` where the instance moves.
    fn under(&self, motor: Option<Motor>, material: Option<usize>, moving: bool) -> Placed {
        let outer = match (motor, self.outer) {
            (Some(m), Some(o)) => Some(m * o),
            (m, o) => m.or(o),
        };
        Placed { base: self.base, outer, material: material.or(self.material), moving: moving || self.moving }
    }
}

/// An instance's table, read, and its span.
fn instance_spec(
    value: &Spanned<toml::de::DeValue<'_>>,
    map: &dyn Fn(usize) -> usize,
    joined: &Joined,
) -> Result<(InstanceSpec, Range<usize>), SceneError> {
    let span = value.span();
    let spec =
        InstanceSpec::deserialize(value.clone().into_deserializer()).map_err(|e| syntax_error(joined, &e, map))?;
    Ok((spec, span))
}

/// The one object of an `[[objects]]` section (its header and sub-tables), parsed alone.
fn section_object(section: &str) -> Result<Spanned<toml::de::DeValue<'_>>, toml::de::Error> {
    let mut table = toml::de::DeTable::parse(section)?;
    match table.get_mut().remove("objects").map(Spanned::into_inner) {
        Some(toml::de::DeValue::Array(a)) if a.len() == 1 => Ok(a.into_iter().next().expect("one")),
        _ => Err(serde::de::Error::custom("an `[[objects]]` section holds one object table")),
    }
}

/// A TOML or field error as a located one-line message, its span mapped to the file by `map`.
fn syntax_error(joined: &Joined, e: &toml::de::Error, map: &dyn Fn(usize) -> usize) -> SceneError {
    let text = joined.text.as_str();
    let offset = map(e.span().map_or(0, |s| s.start));
    let (file, line, column) = joined.locate(offset);
    let mut message = e.message().trim().to_string();
    if message == "duplicate key"
        && let Some(key) = e.span().and_then(|s| text.get(map(s.start)..map(s.start) + s.len()))
    {
        message = format!("duplicate key `{}`", key.trim().escape_debug());
    } else if let Some(better) = header_mistake(text, offset).filter(|_| message.starts_with("invalid type")) {
        message = better;
    } else if let Some(key) = key_at(text, offset).filter(|k| !message.contains(k.as_str())) {
        message = format!("field `{key}`: {message}");
    }
    SceneError::Syntax { file, line, column, message: printable(&message) }
}

/// What is wrong when the table header at `offset` writes a single table as a list of tables
/// (`[[render]]`) or a list as a single table (`[lights]`): serde only sees a value of the
/// wrong type (and, for `[[render]]`, reports the type of the table's first field).
fn header_mistake(text: &str, offset: usize) -> Option<String> {
    let line = text.get(offset..)?.lines().next()?.trim();
    let (list, name) = match line.strip_prefix("[[") {
        Some(rest) => (true, rest.split("]]").next()?.trim()),
        None => (false, line.strip_prefix('[')?.split(']').next()?.trim()),
    };
    match (list, name) {
        (true, "camera" | "render") => {
            Some(format!("`[[{name}]]` starts a list of tables, but `{name}` is one table: write `[{name}]`"))
        }
        (false, "lights" | "objects") => {
            Some(format!("`[{name}]` is one table, but `{name}` is a list: write `[[{name}]]` before each entry"))
        }
        _ => None,
    }
}

/// The key assigned at or just before `offset` (`max_depth` in `max_depth = "deep"`),
/// for errors whose message does not name the field.
fn key_at(text: &str, offset: usize) -> Option<String> {
    let before = text.get(..offset.min(text.len()))?;
    let segment = before.rsplit(['\n', '{', ',']).next()?;
    let key = segment.split('=').next()?.trim();
    (!key.is_empty() && segment.contains('=') && key.chars().all(|c| c.is_alphanumeric() || c == '_' || c == '.'))
        .then(|| key.to_string())
}
