// The ghost trail's "every N states": a whole number >= 1, and never so small that the trail has
// more than MAX_GHOSTS copies (hundreds of copies make every frame slow). A refused value is
// replaced and the reason shown next to the field.
export const MAX_GHOSTS = 40;

/// `text` as typed; returns {every, note}: the spacing to use and why it differs from the text (or '').
export function ghostSpacing(text, stateCount) {
  const smallest = Math.max(1, Math.ceil((stateCount - 1) / MAX_GHOSTS));
  const value = Number(text);
  if (!Number.isInteger(value) || value < 1)
    return { every: smallest, note: `"${text}" refused: a whole number of states >= 1 (${smallest} used)` };
  if (value < smallest)
    return { every: smallest, note: `every ${value} would draw more than ${MAX_GHOSTS} ghosts: every ${smallest} used` };
  return { every: value, note: '' };
}
