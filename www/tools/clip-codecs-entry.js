// What www/lib/figure/clip.js uses of the two libraries it records clips with, bundled by www/build.sh
// into www/vendor/clip-codecs.js (loaded only when a clip is encoded). Both are pinned in package.json:
// mediabunny (MPL-2.0) muxes WebCodecs' video into WebM and MP4; gifenc (MIT) quantises and writes GIFs.
export { BufferTarget, Mp4OutputFormat, Output, Quality, VideoSample, VideoSampleSource, WebMOutputFormat } from 'mediabunny';
export { GIFEncoder, quantize } from 'gifenc';
