//! Replacing a scene's viewport by a display's size (`microtrace render --size WxH`, and the
//! firmware's 128x64 OLED). The whole original window stays in view: it is extended about its
//! centre along one axis so that the pixel spacing is the same in x and y (square pixels).

use crate::model::{Description, Viewport};

impl<L> Description<L> {
    /// Sets the viewport to `width` x `height` pixels (both at least 1) and widens the window
    /// about its centre so the old window fits and pixels stay square.
    pub fn fit_to_size(&mut self, width: u16, height: u16) {
        let (width, height) = (width.clamp(1, 32768), height.clamp(1, 32768));
        self.viewport = Viewport { x1: 0, x2: width - 1, y1: 0, y2: height - 1 };
        let window = &mut self.window;
        let (centre_x, centre_y) = ((window.x1 + window.x2) / 2.0, (window.y1 + window.y2) / 2.0);
        let (half_width, half_height) = ((window.x2 - window.x1) / 2.0, (window.y2 - window.y1) / 2.0);
        // Samples sit on the window's edges (pixel x1 at wx1, x2 at wx2: digest §3.1), so the
        // spacing is the extent over (pixels − 1).
        let steps_x = f64::from(width - 1);
        let steps_y = f64::from(height - 1);
        let spacing_x = if steps_x > 0.0 { 2.0 * half_width / steps_x } else { 0.0 };
        let spacing_y = if steps_y > 0.0 { 2.0 * half_height / steps_y } else { 0.0 };
        let spacing = spacing_x.max(spacing_y);
        let new_half_width = if steps_x > 0.0 { spacing * steps_x / 2.0 } else { half_width };
        let new_half_height = if steps_y > 0.0 { spacing * steps_y / 2.0 } else { half_height };
        window.x1 = centre_x - new_half_width;
        window.x2 = centre_x + new_half_width;
        window.y1 = centre_y - new_half_height;
        window.y2 = centre_y + new_half_height;
    }
}

#[cfg(test)]
mod tests {
    use crate::model::{SceneDescription, Window};

    #[test]
    fn wide_display_extends_the_window_horizontally() {
        let mut scene = SceneDescription::<0> { window: Window { x1: -1.0, x2: 1.0, y1: -1.0, y2: 1.0 }, ..Default::default() };
        scene.fit_to_size(129, 65);
        assert_eq!((scene.viewport.x2, scene.viewport.y2), (128, 64));
        // y spacing 2/64 wins; x extent becomes 128 * 2/64 = 4.
        assert_eq!(scene.window, Window { x1: -2.0, x2: 2.0, y1: -1.0, y2: 1.0 });
    }

    #[test]
    fn tall_display_extends_vertically_about_the_centre() {
        let mut scene = SceneDescription::<0> { window: Window { x1: 10.0, x2: 14.0, y1: 0.0, y2: 2.0 }, ..Default::default() };
        scene.fit_to_size(5, 9);
        // x spacing 4/4 = 1 wins over 2/8; y extent 8 about centre 1.
        assert_eq!(scene.window, Window { x1: 10.0, x2: 14.0, y1: -3.0, y2: 5.0 });
    }
}
