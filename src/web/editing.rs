//! Hands on the scene from the page: picking, moving, adding and removing spheres; scenes as files and
//! the compact form links carry; the mesh and pictures as downloads (one readback each, on demand).

use super::parameters::value_to_js;
use super::{Polling, View, js_error, pack_spheres, unpack_spheres};
use crate::device::{read_texture, render_target};
use crate::export::{MeshFormat, encode};
use crate::scene::file::{self as scene_file, SceneFile};
use crate::scene::json::Json;
use crate::scene::sphere::{self, SceneError};
use crate::{Scene, Sphere};
use glam::Vec3;
use wasm_bindgen::prelude::*;

/// A scene document (JSON text) of `spheres` (7 numbers each) and the page's settings (a JSON object
/// of parameter names and values); throws with what is wrong.
#[wasm_bindgen]
pub fn save_scene(spheres: Vec<f32>, settings_json: &str) -> Result<String, JsError> {
    let settings = Json::parse(settings_json).map_err(|e| js_error(e.message))?;
    Ok(SceneFile::new(unpack_spheres(&spheres)?, &settings).map_err(js_error)?.to_json())
}

/// Refuses a file larger than a scene document can be, before the page reads it.
#[wasm_bindgen]
pub fn check_scene_size(bytes: f64) -> Result<(), JsError> {
    scene_file::check_size(bytes as u64).map_err(js_error)
}

/// Reads a scene document: `{ spheres: Float32Array (7 numbers each), settings: { name: value } }`
/// with every setting a scene holds (defaults for those the document leaves out); throws with the
/// field and value that are wrong.
#[wasm_bindgen]
pub fn load_scene(text: &str) -> Result<JsValue, JsError> {
    let scene = SceneFile::parse(text).map_err(js_error)?;
    let settings = js_sys::Object::new();
    for p in scene_file::scene_parameters() {
        let value = match scene.setting(p.name) {
            Some(v) => v.clone(),
            None => p.parse(p.default).map_err(js_error)?,
        };
        js_sys::Reflect::set(&settings, &p.name.into(), &value_to_js(value))
            .map_err(|_| js_error("settings"))?;
    }
    let object = js_sys::Object::new();
    let spheres = js_sys::Float32Array::from(pack_spheres(&scene.spheres).as_slice());
    js_sys::Reflect::set(&object, &"spheres".into(), &spheres).map_err(|_| js_error("spheres"))?;
    js_sys::Reflect::set(&object, &"settings".into(), &settings).map_err(|_| js_error("settings"))?;
    Ok(object.into())
}

/// The compact form of spheres (7 numbers each) for links.
#[wasm_bindgen]
pub fn spheres_text(spheres: Vec<f32>) -> Result<String, JsError> {
    Ok(sphere::spheres_text(&unpack_spheres(&spheres)?))
}

/// Reads the compact form of spheres as 7 numbers each; throws with what is wrong.
#[wasm_bindgen]
pub fn parse_spheres_text(text: &str) -> Result<Vec<f32>, JsError> {
    Ok(pack_spheres(&sphere::parse_spheres_text(text).map_err(js_error)?))
}

#[wasm_bindgen]
impl View {
    /// The sphere under canvas pixel (`x`, `y`) (device pixels from the top left), or -1.
    pub fn pick_sphere(&self, x: f32, y: f32) -> i32 {
        self.renderer.pick_sphere(x, y).map_or(-1, |i| i as i32)
    }

    /// Moves sphere `index` as the pointer moved from (`x0`, `y0`) to (`x1`, `y1`), in the plane facing
    /// the camera, inside the box.
    pub fn move_sphere(&mut self, index: u32, x0: f32, y0: f32, x1: f32, y1: f32) -> Result<(), JsError> {
        self.renderer.move_sphere(index as usize, (x0, y0), (x1, y1)).map_err(js_error)
    }

    /// Adds a still sphere under pixel (`x`, `y`), at the depth of the box's centre; returns its index.
    pub fn add_sphere(&mut self, x: f32, y: f32) -> Result<u32, JsError> {
        self.renderer.add_sphere(x, y).map(|i| i as u32).map_err(js_error)
    }

    /// Removes sphere `index` (the last one stays).
    pub fn remove_sphere(&mut self, index: u32) -> Result<(), JsError> {
        self.renderer.edit(|scene| scene.remove_sphere(index as usize)).map_err(js_error)
    }

    /// Sets sphere `index`'s radius (its centre moves inside the box if needed).
    pub fn set_sphere_radius(&mut self, index: u32, radius: f32) -> Result<(), JsError> {
        self.change_sphere(index, |s| Sphere { radius, ..s })
    }

    /// Sets sphere `index`'s charge: 1 adds its term, −1 subtracts it.
    pub fn set_sphere_charge(&mut self, index: u32, charge: f32) -> Result<(), JsError> {
        self.change_sphere(index, |s| Sphere { charge, ..s })
    }

    /// Sets sphere `index`'s velocity (box half-widths per second); zero freezes it.
    pub fn set_sphere_velocity(&mut self, index: u32, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        self.change_sphere(index, |s| Sphere { velocity: Vec3::new(x, y, z), ..s })
    }

    fn change_sphere(&mut self, index: u32, f: impl FnOnce(Sphere) -> Sphere) -> Result<(), JsError> {
        let i = index as usize;
        self.renderer
            .edit(|scene: &mut Scene| {
                let sphere = *scene
                    .spheres()
                    .get(i)
                    .ok_or_else(|| SceneError(format!("there is no sphere {}", i + 1)))?;
                scene.set_sphere(i, f(sphere))
            })
            .map_err(js_error)
    }

    /// Where each point of `xyz` (three numbers a point) is on the canvas: `[x, y]` in device pixels
    /// per point, NaN for one behind the eye. For marks drawn over the figure (the critical points).
    pub fn points_on_screen(&self, xyz: &[f32]) -> Vec<f32> {
        let view = self.renderer.camera_view();
        xyz.chunks_exact(3)
            .flat_map(|p| view.pixel_of(glam::Vec3::from_slice(p)).map_or([f32::NAN; 2], |q| [q.x, q.y]))
            .collect()
    }

    /// Where sphere `index` is on the canvas: [x, y, radius] in device pixels, or nothing.
    pub fn sphere_on_screen(&self, index: u32) -> Option<Vec<f32>> {
        self.renderer.sphere_on_screen(index as usize).map(|v| v.to_vec())
    }

    /// The mesh of the current state as a file (`stl`, `obj` or `ply`): resolves to its bytes. One
    /// readback, queued now; the view goes on drawing meanwhile.
    pub fn export_mesh(&mut self, format: &str) -> Result<js_sys::Promise, JsError> {
        let format = MeshFormat::parse(format).map_err(js_error)?;
        let readback = self.renderer.mesh_readback();
        let device = self.device.clone();
        Ok(wasm_bindgen_futures::future_to_promise(async move {
            let _polling = Polling::start(&device);
            let mesh = readback.finish().await.map_err(|e| JsValue::from(js_error(e)))?;
            let bytes = encode(&mesh, format, format.default_scale());
            Ok(js_sys::Uint8Array::from(bytes.as_slice()).into())
        }))
    }

    /// What the shape of the current mesh is worked out from (`mesh_shape`, on the page's mesher worker
    /// where there is one): resolves to `[vertex count, triangles (Uint32Array, three indices each)]`.
    /// On the CPU path the mesh is at hand; on the GPU path it is one readback, queued now and asked for
    /// only on demand, never every frame.
    pub fn mesh_triangles(&mut self) -> js_sys::Promise {
        // A level-of-detail frame leaves out what is outside the view: its shape is the whole mesh's.
        let readback = if self.renderer.mesh_culled() {
            self.renderer.mesh_readback()
        } else {
            self.renderer.drawn_mesh_readback()
        };
        let device = self.device.clone();
        wasm_bindgen_futures::future_to_promise(async move {
            let _polling = Polling::start(&device);
            let mesh = readback.finish().await.map_err(|e| JsValue::from(js_error(e)))?;
            let triangles = js_sys::Uint32Array::from(mesh.triangles.as_flattened());
            Ok(js_sys::Array::of2(&(mesh.positions.len() as u32).into(), &triangles).into())
        })
    }

    /// Draws the current state once at `width` × `height` pixels (without advancing the animation) and
    /// resolves to its pixels, RGBA8 sRGB, rows top to bottom: pictures at any size, on demand.
    pub fn render_pixels(&mut self, width: u32, height: u32) -> Result<js_sys::Promise, JsError> {
        let (old_width, old_height) = self.renderer.size();
        self.renderer.resize(width, height).map_err(js_error)?;
        let format = self.renderer.format();
        let texture = render_target(&self.device, width, height, format);
        self.renderer.render(&texture.create_view(&wgpu::TextureViewDescriptor::default()));
        self.renderer.resize(old_width, old_height).map_err(js_error)?;
        let (device, queue) = (self.device.clone(), self.renderer.queue().clone());
        let bgra = matches!(format, wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb);
        Ok(wasm_bindgen_futures::future_to_promise(async move {
            let _polling = Polling::start(&device);
            let mut pixels = read_texture(&device, &queue, &texture).await;
            if bgra {
                pixels.chunks_exact_mut(4).for_each(|p| p.swap(0, 2));
            }
            Ok(js_sys::Uint8Array::from(pixels.as_slice()).into())
        }))
    }
}
