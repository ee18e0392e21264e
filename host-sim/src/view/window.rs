//! Opening the SDL window safely: check for a display first and catch SDL's panics.

use anyhow::bail;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay, SimulatorEvent, Window};

pub const NO_DISPLAY: &str = "no display available for the simulator window; \
     render headless instead: `microtrace render SCENE.mts --out IMAGE.png`";

/// The window, opened on its first update.
pub struct View {
    pub window: Window,
}

impl View {
    /// Opens the window and shows `display`, or explains why it cannot.
    pub fn open(title: &str, settings: &OutputSettings, display: &SimulatorDisplay<Rgb888>) -> anyhow::Result<Self> {
        let has_display = ["DISPLAY", "WAYLAND_DISPLAY"].iter().any(|name| std::env::var_os(name).is_some_and(|v| !v.is_empty()));
        if !has_display {
            bail!("{NO_DISPLAY} (neither DISPLAY nor WAYLAND_DISPLAY is set)");
        }
        let hook = std::panic::take_hook();
        std::panic::set_hook(Box::new(|_| {}));
        let opened = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let mut window = Window::new(title, settings);
            window.update(display);
            window
        }));
        std::panic::set_hook(hook);
        match opened {
            Ok(window) => Ok(Self { window }),
            Err(panic) => {
                let reason = panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                bail!("{NO_DISPLAY} (SDL could not open a window: {reason})")
            }
        }
    }

    /// Shows `display` and returns the events since the last update.
    pub fn update(&mut self, display: &SimulatorDisplay<Rgb888>) -> Vec<SimulatorEvent> {
        self.window.update(display);
        self.window.events().collect()
    }
}
