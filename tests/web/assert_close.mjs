// The web tests' comparison of an answer with the CLI's JSON: numbers equal within 1e-14
// (relative), since printed angles and the closure quality are rounded arithmetic where the
// browser's libm and glibc may differ in the last bit (every decision is exact and equal;
// docs/web.md); arrays, objects (the same keys) and everything else exactly.
import assert from 'node:assert/strict';

export function assertClose(actual, expected, path = '$') {
  if (typeof expected === 'number') {
    assert.ok(typeof actual === 'number' && Math.abs(actual - expected) <= 1e-14 * Math.max(1, Math.abs(expected)), `${path}: ${actual} vs ${expected}`);
  } else if (Array.isArray(expected)) {
    assert.ok(Array.isArray(actual) && actual.length === expected.length, `${path}: ${JSON.stringify(actual)} vs ${JSON.stringify(expected)}`);
    expected.forEach((x, i) => assertClose(actual[i], x, `${path}[${i}]`));
  } else if (expected && typeof expected === 'object') {
    assert.deepEqual(Object.keys(actual).sort(), Object.keys(expected).sort(), path);
    for (const k of Object.keys(expected)) assertClose(actual[k], expected[k], `${path}.${k}`);
  } else {
    assert.equal(actual, expected, path);
  }
}
