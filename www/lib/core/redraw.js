// How many frames a figure draws after a change while it is still (paused, or at speed 0). The GPU
// reports a frame's counts a frame or two after it is drawn (`Renderer::stats` reads them through a
// ring of staging buffers), and a mesh that did not fit grows its buffers only once they are in.

/**
 * A setting changed, or a renderer started: the frame, the one after it (when the counts of the first
 * come back, a mesh that overflowed its buffers is drawn again in grown ones) and one more to show the
 * statistics of the grown mesh.
 */
export const SETTLE_FRAMES = 3;

/**
 * The picture changed but not the mesh's settings (a new size, background, selected cell or sphere
 * list): the frame and one more, so that the statistics read back are of the new picture.
 */
export const PICTURE_FRAMES = 2;

/** Something to show once, as it is (a sphere dragged, a sync leader's spheres, a picture for print). */
export const ONE_FRAME = 1;
