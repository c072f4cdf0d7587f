// Decodes the PNG screenshots chromium takes (8-bit RGB or RGBA, not interlaced) into pixels, so
// the test judges the rendered image itself rather than trusting the page's word for it.
import { inflateSync } from 'node:zlib';

export function decodePng(buffer) {
  const signature = [137, 80, 78, 71, 13, 10, 26, 10];
  signature.forEach((byte, i) => { if (buffer[i] !== byte) throw new Error('not a PNG'); });
  let offset = 8;
  let width = 0, height = 0, colourType = 0;
  const data = [];
  while (offset < buffer.length) {
    const length = buffer.readUInt32BE(offset);
    const type = buffer.toString('latin1', offset + 4, offset + 8);
    const body = buffer.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0);
      height = body.readUInt32BE(4);
      const bitDepth = body[8];
      colourType = body[9];
      if (bitDepth !== 8 || (colourType !== 2 && colourType !== 6) || body[12] !== 0)
        throw new Error(`unsupported PNG (bit depth ${bitDepth}, colour type ${colourType}, interlace ${body[12]})`);
    } else if (type === 'IDAT') data.push(body);
    else if (type === 'IEND') break;
    offset += 12 + length;
  }
  const channels = colourType === 6 ? 4 : 3;
  const raw = inflateSync(Buffer.concat(data));
  const stride = width * channels;
  const pixels = Buffer.alloc(width * height * 4);
  const previous = Buffer.alloc(stride);
  const row = Buffer.alloc(stride);
  for (let y = 0; y < height; y += 1) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x += 1) {
      const left = x >= channels ? row[x - channels] : 0;
      const up = previous[x];
      const upLeft = x >= channels ? previous[x - channels] : 0;
      let predictor = 0;
      if (filter === 1) predictor = left;
      else if (filter === 2) predictor = up;
      else if (filter === 3) predictor = (left + up) >> 1;
      else if (filter === 4) {
        const p = left + up - upLeft;
        const pa = Math.abs(p - left), pb = Math.abs(p - up), pc = Math.abs(p - upLeft);
        predictor = pa <= pb && pa <= pc ? left : pb <= pc ? up : upLeft;
      } else if (filter !== 0) throw new Error(`bad PNG filter ${filter}`);
      row[x] = (line[x] + predictor) & 0xff;
    }
    for (let x = 0; x < width; x += 1) {
      pixels[(y * width + x) * 4] = row[x * channels];
      pixels[(y * width + x) * 4 + 1] = row[x * channels + 1];
      pixels[(y * width + x) * 4 + 2] = row[x * channels + 2];
      pixels[(y * width + x) * 4 + 3] = channels === 4 ? row[x * channels + 3] : 255;
    }
    row.copy(previous);
  }
  return { width, height, pixels };
}

/// Share of pixels whose colour differs from the most common one (the background), and the number
/// of distinct colours (coarsely quantised).
export function imageContent(image) {
  const counts = new Map();
  const { pixels } = image;
  for (let i = 0; i < pixels.length; i += 4) {
    const key = ((pixels[i] >> 3) << 10) | ((pixels[i + 1] >> 3) << 5) | (pixels[i + 2] >> 3);
    counts.set(key, (counts.get(key) || 0) + 1);
  }
  const total = pixels.length / 4;
  const background = Math.max(...counts.values());
  return { foregroundShare: 1 - background / total, distinctColours: counts.size };
}

/// Share of pixels that differ by more than `threshold` in any channel between two images of one size.
export function changedShare(a, b, threshold = 24) {
  if (a.width !== b.width || a.height !== b.height) return 1;
  let changed = 0;
  for (let i = 0; i < a.pixels.length; i += 4) {
    if (Math.abs(a.pixels[i] - b.pixels[i]) > threshold || Math.abs(a.pixels[i + 1] - b.pixels[i + 1]) > threshold ||
        Math.abs(a.pixels[i + 2] - b.pixels[i + 2]) > threshold) changed += 1;
  }
  return changed / (a.pixels.length / 4);
}
