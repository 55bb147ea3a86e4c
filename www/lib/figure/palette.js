// The figure's colours in each theme, as custom properties of its shadow root's host: the dark theme's
// (the default) and the light theme's (theme="light", and theme="auto" where the reader prefers light).
// A page's own properties (--metaballs-text, …) take their place. Every text colour meets WCAG's 4.5:1
// on its box in its theme (tests/e2e/phone.test.js measures each one drawn).

export const DARK = `
  --panel: var(--metaballs-panel-background, rgba(14, 17, 24, 0.88));
  --panel-solid: var(--metaballs-panel-background, rgb(14, 17, 24));
  --text: var(--metaballs-text, #e6e9ef);
  --muted: var(--metaballs-muted, #a9b1c2);
  --accent: var(--metaballs-accent, #e77661);
  --button: #232838;
  --button-hover: #2c3245;
  --border: #3d4559;
  --on-accent: #1a0d0a;
  --in: #ff9a3d;
  --out: #7aa7ff;
  --bad: #ff6b5e;
  --warn: #ffb86b;`;

export const LIGHT = `
  --panel: var(--metaballs-panel-background, rgba(250, 251, 253, 0.92));
  --panel-solid: var(--metaballs-panel-background, rgb(250, 251, 253));
  --text: var(--metaballs-text, #1b1f27);
  --muted: var(--metaballs-muted, #4a5263);
  --accent: var(--metaballs-accent, #b2412c);
  --button: #e8ebf1;
  --button-hover: #dde1e9;
  --border: #a9b1c2;
  --on-accent: #ffffff;
  --in: #a84b00;
  --out: #2455c3;
  --bad: #b3261e;
  --warn: #8a4500;
  background: var(--metaballs-poster-color, #e4e8ef);
  color-scheme: light;`;
