/**
 * Named per-element data (the "property" systems of pmp and OpenMesh): one typed array per
 * attribute, `itemSize` numbers per element, indexed by the element's id.
 *
 * The mesh owns four sets (vertices, halfedges, edges, faces) and keeps them in step with its own
 * arrays: they grow with its capacity, follow compaction, and give new elements a value when an
 * edit creates them (a midpoint vertex gets the blend of its edge's end points). Positions are the
 * vertex attribute `position` (float64 × 3), so they travel through edits like any other.
 *
 * @example
 *   const colour = mesh.vertexAttributes.add('color', 'uint8', 3);
 *   colour.data.set([255, 0, 0], 3 * v);
 */
import { InvalidInputError } from './errors.js';
import { type Memory, newArrayLike } from './memory.js';
import { permuteItems, type Scratch } from './permute.js';

export const attributeArrayTypes = {
  int8: Int8Array,
  uint8: Uint8Array,
  int16: Int16Array,
  uint16: Uint16Array,
  int32: Int32Array,
  uint32: Uint32Array,
  float32: Float32Array,
  float64: Float64Array,
} as const;

export type AttributeType = keyof typeof attributeArrayTypes;
export type AttributeArray = InstanceType<(typeof attributeArrayTypes)[AttributeType]>;

/**
 * How an edit fills the attribute of an element it creates from others:
 * `linear` blends them with the edit's weights (positions, colours, texture coordinates),
 * `copy` takes the first source as is (labels, ids: averaging them means nothing).
 */
export type Interpolation = 'linear' | 'copy';

export interface Attribute {
  readonly name: string;
  readonly type: AttributeType;
  readonly itemSize: number;
  readonly interpolation: Interpolation;
  /** `capacity × itemSize` numbers; replaced (not resized in place) when the mesh grows. */
  data: AttributeArray;
}

export function attributeTypeOf(data: AttributeArray): AttributeType {
  for (const [type, ArrayType] of Object.entries(attributeArrayTypes)) {
    if (data instanceof ArrayType) return type as AttributeType;
  }
  throw new InvalidInputError('attribute data must be a typed array');
}

export class AttributeSet {
  private readonly byName = new Map<string, Attribute>();
  private capacity: number;

  constructor(capacity = 0) {
    this.capacity = capacity;
  }

  /**
   * Adds an attribute filled with zeros, or returns the existing one of the same name when its
   * type and item size match.
   * @throws InvalidInputError when the name is taken by an attribute of another shape, or the type
   *   or item size is not one an attribute can have.
   */
  add(name: string, type: AttributeType, itemSize: number, interpolation?: Interpolation): Attribute {
    const existing = this.byName.get(name);
    if (existing) {
      if (existing.type !== type || existing.itemSize !== itemSize) {
        throw new InvalidInputError(
          `attribute '${name}' already exists as ${existing.type} × ${existing.itemSize}, not ${type} × ${itemSize}`,
        );
      }
      return existing;
    }
    // the type may come from a file or a document: only the table's own keys name an array type
    if (!Object.hasOwn(attributeArrayTypes, type)) {
      const types = Object.keys(attributeArrayTypes).join(', ');
      throw new InvalidInputError(`attribute '${name}': unknown attribute type '${type}' (types: ${types})`);
    }
    if (!Number.isInteger(itemSize) || itemSize < 1) {
      throw new InvalidInputError(`attribute '${name}': item size must be a positive integer, not ${itemSize}`);
    }
    const attribute: Attribute = {
      name,
      type,
      itemSize,
      interpolation: interpolation ?? (type.startsWith('float') ? 'linear' : 'copy'),
      data: new attributeArrayTypes[type](this.capacity * itemSize),
    };
    this.byName.set(name, attribute);
    return attribute;
  }

  get(name: string): Attribute | undefined {
    return this.byName.get(name);
  }

  has(name: string): boolean {
    return this.byName.has(name);
  }

  remove(name: string): boolean {
    return this.byName.delete(name);
  }

  get size(): number {
    return this.byName.size;
  }

  [Symbol.iterator](): IterableIterator<Attribute> {
    return this.byName.values();
  }

  /** Reallocates every attribute for `capacity` elements (in `memory`), keeping the first `used` of them. */
  resize(capacity: number, used: number, memory?: Memory): void {
    for (const attribute of this.byName.values()) {
      const next = newArrayLike(attribute.data, capacity * attribute.itemSize, memory);
      next.set(attribute.data.subarray(0, Math.min(used, capacity) * attribute.itemSize));
      attribute.data = next;
    }
    this.capacity = capacity;
  }

  /** Element `dst` takes the values of element `src`. */
  copy(dst: number, src: number): void {
    for (const { data, itemSize } of this.byName.values()) {
      data.copyWithin(dst * itemSize, src * itemSize, (src + 1) * itemSize);
    }
  }

  /**
   * Element `dst` takes the weighted sum of `sources` (weights should add up to 1) for `linear`
   * attributes, and the first source's value for `copy` ones. Integer types are rounded.
   */
  blend(dst: number, sources: ArrayLike<number>, weights: ArrayLike<number>): void {
    for (const { data, itemSize, interpolation } of this.byName.values()) {
      if (interpolation === 'copy' || sources.length === 1) {
        data.copyWithin(dst * itemSize, sources[0] * itemSize, (sources[0] + 1) * itemSize);
        continue;
      }
      const round = !(data instanceof Float32Array || data instanceof Float64Array);
      for (let k = 0; k < itemSize; k++) {
        let sum = 0;
        for (let i = 0; i < sources.length; i++) sum += weights[i] * data[sources[i] * itemSize + k];
        data[dst * itemSize + k] = round ? Math.round(sum) : sum;
      }
    }
  }

  /** Keeps element `i` at `oldToNew[i]` (dropped where it is -1); used by compaction (see `permute.ts`). */
  permute(oldToNew: Int32Array, newCount: number, scratch: Scratch): void {
    for (const attribute of this.byName.values()) {
      attribute.data = permuteItems(attribute.data, attribute.itemSize, oldToNew, newCount, scratch);
    }
    this.capacity = newCount;
  }

  /** A deep copy holding the first `used` elements (with room for `capacity`). */
  clone(capacity: number, used: number): AttributeSet {
    const copy = new AttributeSet(capacity);
    for (const attribute of this.byName.values()) {
      const data = new attributeArrayTypes[attribute.type](capacity * attribute.itemSize);
      data.set(attribute.data.subarray(0, used * attribute.itemSize));
      copy.byName.set(attribute.name, { ...attribute, data });
    }
    return copy;
  }
}
