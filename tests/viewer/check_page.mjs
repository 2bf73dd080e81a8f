// Opens a page in headless Chromium with software WebGL, waits for the page to say it has
// rendered, and prints what a person would have seen as JSON on stdout: every console error and
// uncaught exception, every request that left the machine, and per screenshot the pixels of the
// canvas's two halves. Exits 0 only if the page rendered with no error and no request.
//
//   node check_page.mjs --chromium /usr/bin/chromium --page view.html
//       [--hash '#bare'] [--size 1200x700] [--timeout 120] [--save-png shot.png]
//       [--shots 'first;show-bands,show-sharp;show-patches']
//
// --shots: screenshots in order, each after clicking the elements whose ids it lists (the
// clicks add up); one plain screenshot by default.
//
// Why the DevTools protocol over --remote-debugging-pipe rather than grepping Chromium's
// --enable-logging output: the log mixes page messages with the browser's own errors (D-Bus,
// GPU probing) in a format that changes between versions, and says nothing of exceptions thrown
// before a handler is set. The protocol reports console calls (Runtime.consoleAPICalled),
// exceptions (Runtime.exceptionThrown), browser-side messages such as WebGL errors
// (Log.entryAdded) and requests (Network.requestWillBeSent) as typed events of this page only,
// and takes the screenshot in the same session. A pipe needs no port, so parallel tests cannot
// collide. Every wait is bounded by --timeout.

import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { inflateSync } from 'node:zlib';

function parseArguments(argv) {
    const args = { size: '1200x700', timeout: '120', hash: '', shots: '' };
    for (let i = 0; i < argv.length; i += 2) {
        if (!argv[i].startsWith('--') || argv[i + 1] === undefined) throw new Error(`bad argument ${argv[i]}`);
        args[argv[i].slice(2).replace('-', '_')] = argv[i + 1];
    }
    if (!args.chromium || !args.page) throw new Error('--chromium and --page are required');
    const [width, height] = args.size.split('x').map(Number);
    return { ...args, width, height, timeoutMs: Number(args.timeout) * 1000 };
}

/// Chromium driven over the DevTools protocol on file descriptors 3 (to it) and 4 (from it),
/// messages ended by a NUL byte.
class Browser {
    constructor(chromium, width, height) {
        this.profile = mkdtempSync(join(tmpdir(), 'resharp-chromium-'));
        this.process = spawn(chromium, [
            '--headless', '--no-sandbox', '--remote-debugging-pipe',
            // Software WebGL: ANGLE on SwiftShader. Chromium 156 still falls back to it on its
            // own, but warns that the automatic fallback is deprecated; the flag opts in, so the
            // warning goes and a Chromium without the fallback still has WebGL.
            '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
            `--user-data-dir=${this.profile}`, `--window-size=${width},${height}`,
            '--no-first-run', '--no-default-browser-check', '--hide-scrollbars', 'about:blank',
        ], { stdio: ['ignore', 'ignore', 'ignore', 'pipe', 'pipe'] });
        this.nextId = 1;
        this.pending = new Map();
        this.listeners = [];
        this.buffer = Buffer.alloc(0);
        this.process.stdio[4].on('data', (chunk) => this.receive(chunk));
        this.exited = new Promise((done) => this.process.on('exit', done));
    }

    receive(chunk) {
        this.buffer = Buffer.concat([this.buffer, chunk]);
        for (let end = this.buffer.indexOf(0); end >= 0; end = this.buffer.indexOf(0)) {
            const message = JSON.parse(this.buffer.subarray(0, end).toString('utf8'));
            this.buffer = this.buffer.subarray(end + 1);
            if (message.id !== undefined && this.pending.has(message.id)) {
                const { resolve: done, reject } = this.pending.get(message.id);
                this.pending.delete(message.id);
                if (message.error) reject(new Error(`${message.error.message}`));
                else done(message.result);
            } else if (message.method) {
                for (const listener of this.listeners) listener(message);
            }
        }
    }

    send(method, params = {}, sessionId = undefined) {
        const id = this.nextId++;
        const message = JSON.stringify({ id, method, params, ...(sessionId ? { sessionId } : {}) });
        return new Promise((done, reject) => {
            this.pending.set(id, { resolve: done, reject });
            this.process.stdio[3].write(message + '\0');
        });
    }

    async close() {
        try {
            await withTimeout(this.send('Browser.close'), 10000, 'Browser.close');
        } catch {
            this.process.kill('SIGKILL');
        }
        await withTimeout(this.exited, 10000, 'chromium exit').catch(() => this.process.kill('SIGKILL'));
        rmSync(this.profile, { recursive: true, force: true });
    }
}

function withTimeout(promise, ms, what) {
    let timer;
    const timeout = new Promise((_, reject) => {
        timer = setTimeout(() => reject(new Error(`timed out after ${ms} ms: ${what}`)), ms);
    });
    return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

const sleep = (ms) => new Promise((done) => setTimeout(done, ms));

/// The RGBA pixels of an 8-bit, non-interlaced RGB or RGBA PNG (what Chromium writes).
function decodePng(bytes) {
    let offset = 8;
    let width = 0, height = 0, channels = 0;
    const data = [];
    while (offset < bytes.length) {
        const length = bytes.readUInt32BE(offset);
        const type = bytes.toString('latin1', offset + 4, offset + 8);
        const body = bytes.subarray(offset + 8, offset + 8 + length);
        if (type === 'IHDR') {
            width = body.readUInt32BE(0);
            height = body.readUInt32BE(4);
            const [depth, colorType, interlace] = [body[8], body[9], body[12]];
            channels = { 2: 3, 6: 4 }[colorType];
            if (depth !== 8 || !channels || interlace !== 0) throw new Error('unsupported PNG');
        } else if (type === 'IDAT') {
            data.push(body);
        }
        offset += 12 + length;
    }
    const raw = inflateSync(Buffer.concat(data));
    const stride = width * channels;
    const pixels = new Uint8Array(width * height * 4);
    let previous = new Uint8Array(stride);
    for (let y = 0; y < height; ++y) {
        const filter = raw[y * (stride + 1)];
        const row = Uint8Array.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
        for (let i = 0; i < stride; ++i) {
            const left = i >= channels ? row[i - channels] : 0;
            const up = previous[i];
            const upLeft = i >= channels ? previous[i - channels] : 0;
            let predictor = 0;
            if (filter === 1) predictor = left;
            else if (filter === 2) predictor = up;
            else if (filter === 3) predictor = (left + up) >> 1;
            else if (filter === 4) {
                const p = left + up - upLeft;
                const [pa, pb, pc] = [Math.abs(p - left), Math.abs(p - up), Math.abs(p - upLeft)];
                predictor = pa <= pb && pa <= pc ? left : pb <= pc ? up : upLeft;
            }
            row[i] = (row[i] + predictor) & 0xff;
        }
        for (let x = 0; x < width; ++x) {
            for (let c = 0; c < 4; ++c) {
                pixels[(y * width + x) * 4 + c] = c < channels ? row[x * channels + c] : 255;
            }
        }
        previous = row;
    }
    return { width, height, pixels };
}

/// Per half of the rectangle `box` of the image: distinct colours, the share of pixels that are
/// not the white background, coloured pixels (largest minus smallest channel over 40: the
/// viewer's greys stay under 15) and the mean luminance (0-255).
function halfStatistics(image, box) {
    const halves = [];
    for (let half = 0; half < 2; ++half) {
        const x0 = Math.round(box.x + half * box.width / 2), x1 = Math.round(box.x + (half + 1) * box.width / 2);
        const y0 = Math.round(box.y), y1 = Math.round(box.y + box.height);
        const colors = new Set();
        let drawn = 0, colored = 0, luminance = 0, total = 0;
        for (let y = y0; y < Math.min(y1, image.height); ++y) {
            for (let x = x0; x < Math.min(x1, image.width); ++x) {
                const i = (y * image.width + x) * 4;
                const [r, g, b] = [image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]];
                colors.add((r << 16) | (g << 8) | b);
                if (r < 250 || g < 250 || b < 250) ++drawn;
                if (Math.max(r, g, b) - Math.min(r, g, b) > 40) ++colored;
                luminance += 0.2126 * r + 0.7152 * g + 0.0722 * b;
                ++total;
            }
        }
        halves.push({
            distinct_colors: colors.size, drawn_fraction: drawn / total, colored_pixels: colored,
            mean_luminance: luminance / total,
        });
    }
    return halves;
}

async function check(args) {
    const browser = new Browser(args.chromium, args.width, args.height);
    const report = { status: 'not loaded', errors: [], warnings: [], outside_requests: [], shots: [] };
    try {
        const { targetId } = await withTimeout(browser.send('Target.createTarget', { url: 'about:blank' }),
            args.timeoutMs, 'Target.createTarget');
        const { sessionId } = await browser.send('Target.attachToTarget', { targetId, flatten: true });
        const page = (method, params) => withTimeout(browser.send(method, params, sessionId), args.timeoutMs, method);
        browser.listeners.push(({ method, params, sessionId: from }) => {
            if (from !== sessionId) return;
            if (method === 'Runtime.consoleAPICalled') {
                const text = params.args.map((a) => a.value ?? a.description ?? '').join(' ');
                if (params.type === 'error' || params.type === 'assert') report.errors.push(`console.${params.type}: ${text}`);
                if (params.type === 'warning') report.warnings.push(`console.warn: ${text}`);
            } else if (method === 'Runtime.exceptionThrown') {
                const d = params.exceptionDetails;
                report.errors.push(`exception: ${d.exception?.description ?? d.text}`);
            } else if (method === 'Log.entryAdded') {
                const { level, text, source } = params.entry;
                if (level === 'error') report.errors.push(`${source}: ${text}`);
                if (level === 'warning') report.warnings.push(`${source}: ${text}`);
            } else if (method === 'Network.requestWillBeSent') {
                const url = params.request.url;
                if (!/^(file|data|blob|about):/.test(url)) report.outside_requests.push(url);
            }
        });
        for (const domain of ['Runtime', 'Log', 'Page', 'Network']) await page(`${domain}.enable`, {});
        await page('Emulation.setDeviceMetricsOverride',
            { width: args.width, height: args.height, deviceScaleFactor: 1, mobile: false });
        await page('Page.navigate', { url: pathToFileURL(resolve(args.page)).href + args.hash });

        const evaluate = async (expression, awaitPromise = false) =>
            (await page('Runtime.evaluate', { expression, returnByValue: true, awaitPromise })).result.value;
        const deadline = Date.now() + args.timeoutMs;
        for (;;) {  // until the page says how it went, or the deadline
            const status = await evaluate('document.documentElement.dataset.status');
            if (status && status !== 'loading') { report.status = status; break; }
            if (Date.now() > deadline) { report.status = 'timed out'; break; }
            await sleep(100);
        }
        report.viewer = await evaluate('window.resharpViewer ?? null');
        const box = await evaluate(`(() => { const c = document.querySelector('canvas');
            if (!c) return null; const r = c.getBoundingClientRect();
            return { x: r.x, y: r.y, width: r.width, height: r.height }; })()`);
        const shots = args.shots ? args.shots.split(';') : [''];
        for (const [n, clicks] of shots.entries()) {
            for (const id of clicks.split(',').filter(Boolean)) {
                const found = await evaluate(`(() => { const e = document.getElementById(${JSON.stringify(id)});
                    if (!e) return false; e.click(); return true; })()`);
                if (!found) report.errors.push(`no element #${id} to click`);
            }
            // Two animation frames: the click's repaint has reached the screen.
            await evaluate('new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)))', true);
            const { data } = await page('Page.captureScreenshot', { format: 'png' });
            const png = Buffer.from(data, 'base64');
            if (args.save_png) writeFileSync(n === 0 ? args.save_png : args.save_png.replace(/\.png$/, `-${n}.png`), png);
            const image = decodePng(png);
            report.shots.push({ clicks, halves: box ? halfStatistics(image, box) : null });
        }
    } catch (error) {
        report.errors.push(`driver: ${error.message}`);
    } finally {
        await browser.close();
    }
    return report;
}

const args = parseArguments(process.argv.slice(2));
const report = await check(args);
process.stdout.write(JSON.stringify(report, null, 2) + '\n');
const ok = report.status === 'rendered' && report.errors.length === 0 && report.outside_requests.length === 0;
process.exit(ok ? 0 : 1);
