// English: what a refused value says, by code, worded as the table's parser in Rust words it (so a
// figure's notice in English reads as the console's message). Fields: `noun` (the setting), `value`
// (as typed), `min`, `max`, `expected`, `detail`, `spelling` (the attribute given), `text`, `kept`.
export default {
  'refused.not-a-number': '{noun} must be a number, got NaN',
  'refused.infinite': '{noun} must be finite, got infinity',
  'refused.invalid': '{noun} must be {expected}, got {value}',
  'refused.out-of-range': '{noun} must be between {min} and {max}, got {value}',
  'refused.device-limit': '{noun} {value} is more than this device can hold: {detail}',
  'refused.keeping': '{spelling}="{text}": {message}; keeping {kept}',
  'expected.whole': 'a whole number from {min} to {max}',
  'expected.number': 'a number from {min} to {max}',
  'expected.flag': 'true or false (also 1/0, on/off)',
  'expected.colour': 'a colour written #rrggbb',
  'expected.one-of': 'one of {words}',
  'expected.list-of': 'all, none, or a comma list of {words}',
  'expected.slice': 'off, or an axis and a position such as z:0.25 (x, y or z; -1 to 1)',
  'expected.cell': 'off, or a cell of the grid as x,y,z (whole numbers from 0, such as 3,4,5)',
  'expected.spheres': 'x,y,z,radius[,vx,vy,vz] per sphere joined by ; ({detail})',
  'expected.lod-multiple': 'a multiple of {block} with lod=on',
  'expected.text': '{text}',
  'noun.slice-position': 'slice position',
  'noun.sphere-radius': 'sphere radius',
};
