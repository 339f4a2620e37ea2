// Prepended to momentlab.mjs (web/CMakeLists.txt): Emscripten 3.1.6 writes `require` and
// `__dirname` for node, which an ES module does not have; in a browser neither is touched.
const momentlabInNode = typeof process === 'object' && process.versions != null && process.versions.node != null;
const require = momentlabInNode ? (await import('module')).createRequire(import.meta.url) : undefined;
const __dirname = momentlabInNode ? (await import('path')).dirname((await import('url')).fileURLToPath(import.meta.url)) : '';
