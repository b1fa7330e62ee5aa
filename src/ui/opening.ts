/**
 * Opening meshes: a file picked or dropped (a `.gltf` with the buffers it names), a sample model
 * from the menu, and the user's file again with another weld distance. A mesh replaces the one on
 * screen only once it has been read: a file that cannot be read is said, and the mesh stays.
 */
import { CancelledError } from '../workers/client.js';
import type { PageSnapshot as Snapshot } from '../workers/page-copy.js';
import type { OpenOptions } from '../workers/protocol.js';
import { el, replace } from './dom.js';
import { openedEntry } from './share.js';

export interface SampleModel {
  file: string;
  title: string;
}

export interface OpeningActions {
  /** Reads the bytes in the session (rejects with the reason they cannot be read). */
  open(bytes: Uint8Array, name: string, sample: string | null, options: OpenOptions): Promise<Snapshot>;
  /** Shows a mesh just opened, saying so. */
  opened(snapshot: Snapshot, name: string): void;
  say(message: string, role?: 'status' | 'alert'): void;
  showError(title: string, message: string): void;
  hideProgress(): void;
}

export class Opening {
  /** The sample models the server has (`models/index.json`). */
  samples: SampleModel[] = [];
  /** The sample the mesh on screen came from, which a link can name; null for a file of the user's. */
  private sample: string | null = null;
  /** The files the user last opened (picked or dropped), to open again with another weld distance. */
  private userFiles: File[] | null = null;

  constructor(
    private readonly menu: HTMLSelectElement,
    private readonly actions: OpeningActions,
  ) {}

  /** Keeps the sample menu on the model the mesh on screen came from, wherever the history is. */
  shown(snapshot: Snapshot): void {
    this.sample = openedEntry(snapshot)?.sample ?? null;
    this.menu.value = this.sample ?? ''; // blank for a file of the user's
  }

  /** One mesh file, or a `.gltf` with the files it names (its `.bin` buffers) picked or dropped together with it. */
  async openFiles(files: File[], weldTolerance = 0): Promise<boolean> {
    const main = files.find((f) => /\.gltf$/i.test(f.name)) ?? files.find((f) => !/\.(bin|png|jpe?g|webp|ktx2)$/i.test(f.name)) ?? files[0];
    if (!main) return false;
    const others = files.filter((f) => f !== main);
    const resources = new Map(await Promise.all(others.map(async (f) => [f.name, new Uint8Array(await f.arrayBuffer())] as const)));
    // kept (a File is a handle, not a copy) to open again with another weld distance; set before the
    // mesh is shown, so that its File tab offers that, and put back if it cannot be read
    const before = this.userFiles;
    this.userFiles = files;
    const opened = await this.openBytes(new Uint8Array(await main.arrayBuffer()), main.name, null, { resources: resources.size > 0 ? resources : undefined, weldTolerance });
    if (!opened) this.userFiles = before;
    return opened;
  }

  /**
   * The user's file again, its vertices welded within `weldTolerance` (STL, glTF): the File tab's
   * Reopen. False when the mesh on screen is not from a file the page still has.
   */
  async reopen(weldTolerance: number, shownName: string | null): Promise<boolean> {
    if (!(weldTolerance >= 0 && Number.isFinite(weldTolerance))) {
      this.actions.say(`The weld distance must be a number of 0 or more, not ${weldTolerance}.`, 'alert');
      return false;
    }
    if (!this.userFiles || !this.reopenable(shownName)) {
      this.actions.say('Only a file opened from this computer can be opened again; open it once more.', 'alert');
      return false;
    }
    return this.openFiles(this.userFiles, weldTolerance);
  }

  /** Whether the file named (the one on screen) is among those the page still has (see `reopen`). */
  reopenable(name: string | null): boolean {
    return this.userFiles?.some((f) => f.name === name) ?? false;
  }

  /**
   * A file's bytes; `sample` names the sample model they are (null: a file of the user's).
   * `options`: the files a `.gltf` names, and the weld distance (see `OpenOptions`).
   */
  async openBytes(bytes: Uint8Array, name: string, sample: string | null = null, options: OpenOptions = {}): Promise<boolean> {
    try {
      this.actions.say(`Reading ${name}…`);
      this.actions.opened(await this.actions.open(bytes, name, sample, options), name);
      return true;
    } catch (error) {
      this.menu.value = this.sample ?? ''; // the menu shows what stays open
      const { message } = error as Error;
      if (error instanceof CancelledError) this.actions.say(`${message}; the previous mesh stays.`);
      else {
        this.actions.say(`Could not open ${name}: ${message}. The previous mesh stays.`, 'alert');
        this.actions.showError(`Could not open ${name}`, `${message}. The mesh you had is still open.`);
      }
      return false;
    } finally {
      this.actions.hideProgress();
    }
  }

  async openSample(file: string): Promise<boolean> {
    // the list is what exists: a server may answer any other name with its index page
    if (this.samples.length > 0 && !this.samples.some((s) => s.file === file)) {
      this.actions.say(`There is no sample called ${file}.`, 'alert');
      return false;
    }
    const response = await fetch(`${import.meta.env.BASE_URL}models/${encodeURIComponent(file)}`);
    if (!response.ok) {
      this.actions.say(`There is no sample called ${file} (${response.status}).`, 'alert');
      return false;
    }
    return this.openBytes(new Uint8Array(await response.arrayBuffer()), file, file);
  }

  async loadSampleList(): Promise<void> {
    const response = await fetch(`${import.meta.env.BASE_URL}models/index.json`);
    this.samples = response.ok ? ((await response.json()) as SampleModel[]) : [];
    replace(this.menu, ...this.samples.map((s) => el('option', { value: s.file }, s.title)));
  }
}
