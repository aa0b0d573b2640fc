#include "vtkLightFieldImageCache.h"

#include "lfdTexelSource.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"

#include <OpenImageIO/imagecache.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>
#include <thread>

vtkStandardNewMacro(vtkLightFieldImageCache);

namespace
{
using Cache = OIIO::ImageCache;

// The tiles one thread keeps pinned for one pass: a bilinear lookup's 2 x 2
// texels and the neighbouring rays' share them, so most texel reads end
// here, without a call into the cache (whose own lookup takes a lock).
struct TileTable
{
  static constexpr int Size = 8;
  struct Entry
  {
    int View = -1;
    int X = 0; // tile origin
    int Y = 0;
    Cache::Tile* Tile = nullptr;
    const unsigned char* Pixels = nullptr;
    std::uint64_t Used = 0;
  };
  std::array<Entry, Size> Entries;
  std::uint64_t Clock = 0;
  Cache::Perthread* Thread = nullptr;
};

// Sources are told apart by a serial number that is never reused, so a
// thread's memory of a destroyed source can never match a new one.
std::atomic<std::uint64_t> NextSerial{ 1 };

// One pass of the light field through the cache.
class PassTexels : public lfd::TexelSource
{
public:
  PassTexels(Cache* cache, const std::vector<std::string>& files, int pass)
    : CacheOf(cache)
    , Files(files)
    , Serial(NextSerial++)
  {
    this->ValueBytes = vtkLightField::GetPassScalarType(pass) == VTK_FLOAT ? 4 : 1;
    this->PixelBytes = vtkLightField::GetPassComponents(pass) * this->ValueBytes;
    for (const std::string& file : files)
    {
      this->Handles.push_back(cache->get_image_handle(OIIO::ustring(file)));
    }
    const OIIO::ImageSpec* spec =
      files.empty() ? nullptr : cache->imagespec(OIIO::ustring(files[0]), 0, 0);
    this->TileWidth = spec && spec->tile_width > 0 ? spec->tile_width : 1;
    this->TileHeight = spec && spec->tile_height > 0 ? spec->tile_height : 1;
    this->Zero.assign(static_cast<size_t>(this->PixelBytes), 0);
  }

  ~PassTexels() override
  {
    for (auto& entry : this->Tables)
    {
      for (TileTable::Entry& slot : entry.second->Entries)
      {
        if (slot.Tile)
        {
          this->CacheOf->release_tile(slot.Tile);
        }
      }
      this->CacheOf->destroy_thread_info(entry.second->Thread);
    }
  }

  const void* Texel(int view, int x, int y) const override
  {
    TileTable& table = this->TableOfThisThread();
    const int tx = x - x % this->TileWidth;
    const int ty = y - y % this->TileHeight;
    TileTable::Entry* oldest = &table.Entries[0];
    for (TileTable::Entry& slot : table.Entries)
    {
      if (slot.View == view && slot.X == tx && slot.Y == ty)
      {
        slot.Used = ++table.Clock;
        return slot.Pixels +
          (static_cast<size_t>(y - ty) * this->TileWidth + (x - tx)) * this->PixelBytes;
      }
      if (slot.Used < oldest->Used)
      {
        oldest = &slot;
      }
    }
    if (oldest->Tile)
    {
      this->CacheOf->release_tile(oldest->Tile);
    }
    *oldest = TileTable::Entry();
    Cache::Tile* tile = this->CacheOf->get_tile(this->Handles[view], table.Thread, 0, 0, x, y, 0);
    OIIO::TypeDesc format;
    const void* pixels = tile ? this->CacheOf->tile_pixels(tile, format) : nullptr;
    if (!pixels || static_cast<int>(format.size()) != this->ValueBytes)
    {
      this->Fail(view, pixels ? "the tile's pixels are not of the pass's type" : "");
      if (tile)
      {
        this->CacheOf->release_tile(tile);
      }
      return this->Zero.data();
    }
    *oldest = { view, tx, ty, tile, static_cast<const unsigned char*>(pixels), ++table.Clock };
    return oldest->Pixels +
      (static_cast<size_t>(y - ty) * this->TileWidth + (x - tx)) * this->PixelBytes;
  }

  /// Calls visit(values, count) for the pixels of every tile of every view.
  template<typename Visit>
  void ForEachTile(int width, int height, Visit&& visit) const
  {
    for (size_t view = 0; view < this->Handles.size(); ++view)
    {
      for (int ty = 0; ty < height; ty += this->TileHeight)
      {
        for (int tx = 0; tx < width; tx += this->TileWidth)
        {
          const int rows = std::min(this->TileHeight, height - ty);
          const int columns = std::min(this->TileWidth, width - tx);
          for (int row = 0; row < rows; ++row)
          {
            // Through Texel(): the same pinned tiles and the same errors.
            const auto* first =
              static_cast<const unsigned char*>(this->Texel(static_cast<int>(view), tx, ty + row));
            const bool zero = first == this->Zero.data();
            for (int column = 0; column < columns; ++column)
            {
              visit(zero ? first : first + column * this->PixelBytes);
            }
          }
        }
      }
    }
  }

  std::string Error() const
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    return this->FirstError;
  }

private:
  TileTable& TableOfThisThread() const
  {
    // Each thread remembers the tables of the few sources it used last.
    struct Remembered
    {
      std::uint64_t Serial = 0;
      TileTable* Table = nullptr;
    };
    thread_local std::array<Remembered, 4> remembered;
    thread_local unsigned next = 0;
    for (const Remembered& entry : remembered)
    {
      if (entry.Serial == this->Serial)
      {
        return *entry.Table;
      }
    }
    std::lock_guard<std::mutex> lock(this->Mutex);
    std::unique_ptr<TileTable>& table = this->Tables[std::this_thread::get_id()];
    if (!table)
    {
      // Owned here, not by the thread: it outlives threads and is destroyed
      // with the source (a thread id is reused only after its thread ended).
      table.reset(new TileTable);
      table->Thread = this->CacheOf->create_thread_info();
    }
    remembered[next++ % remembered.size()] = { this->Serial, table.get() };
    return *table;
  }

  void Fail(int view, const std::string& problem) const
  {
    std::string message = problem.empty() ? this->CacheOf->geterror() : problem;
    std::lock_guard<std::mutex> lock(this->Mutex);
    if (this->FirstError.empty())
    {
      message.erase(std::remove(message.begin(), message.end(), '\n'), message.end());
      this->FirstError =
        this->Files[view] + ": " + (message.empty() ? "cannot read a tile" : message);
    }
  }

  Cache* CacheOf;
  std::vector<std::string> Files;
  std::vector<Cache::ImageHandle*> Handles;
  std::uint64_t Serial;
  int ValueBytes = 1;
  int PixelBytes = 1;
  int TileWidth = 1;
  int TileHeight = 1;
  std::vector<unsigned char> Zero;
  mutable std::mutex Mutex;
  mutable std::map<std::thread::id, std::unique_ptr<TileTable>> Tables;
  mutable std::string FirstError;
};
}

//------------------------------------------------------------------------------
struct vtkLightFieldImageCache::Internals
{
  Cache* ImageCache = Cache::create(false);
  std::unique_ptr<PassTexels> Passes[vtkLightField::NUMBER_OF_PASSES];
  int Width = 0;
  int Height = 0;
  bool LabelsScanned = false;
  std::array<bool, 256> Labels{};
  std::string Error;

  ~Internals()
  {
    for (auto& pass : this->Passes)
    {
      pass.reset();
    }
    Cache::destroy(this->ImageCache, true);
  }

  vtkTypeInt64 Statistic(const char* name) const
  {
    long long value = 0;
    if (!this->ImageCache->getattribute(name, OIIO::TypeInt64, &value))
    {
      int small = 0;
      this->ImageCache->getattribute(name, small);
      value = small;
    }
    return value;
  }
};

//------------------------------------------------------------------------------
vtkLightFieldImageCache::vtkLightFieldImageCache()
  : CacheSize(0)
  , Internal(new Internals)
{
  // Every view of every pass is a file: with the default 100 open files a
  // ring of views reopens files all the time.
  this->Internal->ImageCache->attribute("max_open_files", 1000);
  this->Internal->ImageCache->attribute("forcefloat", 0);
  this->Internal->ImageCache->attribute("autotile", 0);
  this->SetCacheSize(vtkTypeInt64(256) << 20);
}

//------------------------------------------------------------------------------
vtkLightFieldImageCache::~vtkLightFieldImageCache() = default;

//------------------------------------------------------------------------------
void vtkLightFieldImageCache::SetCacheSize(vtkTypeInt64 bytes)
{
  bytes = std::max<vtkTypeInt64>(bytes, vtkTypeInt64(1) << 20);
  if (bytes != this->CacheSize)
  {
    this->CacheSize = bytes;
    this->Internal->ImageCache->attribute(
      "max_memory_MB", static_cast<float>(static_cast<double>(bytes) / (1 << 20)));
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldImageCache::SetPassFiles(int pass,
  const std::vector<std::string>& files,
  int width,
  int height)
{
  if (pass < 0 || pass >= vtkLightField::NUMBER_OF_PASSES)
  {
    vtkErrorMacro("SetPassFiles: invalid pass " << pass << ".");
    return;
  }
  this->Internal->Passes[pass].reset(new PassTexels(this->Internal->ImageCache, files, pass));
  this->Internal->Width = width;
  this->Internal->Height = height;
  this->Internal->LabelsScanned = false;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkLightFieldImageCache::HasPass(int pass)
{
  return pass >= 0 && pass < vtkLightField::NUMBER_OF_PASSES && this->Internal->Passes[pass];
}

//------------------------------------------------------------------------------
const lfd::TexelSource* vtkLightFieldImageCache::GetTexels(int pass)
{
  return this->HasPass(pass) ? this->Internal->Passes[pass].get() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkLightFieldImageCache::HasLabel(int label)
{
  Internals& internal = *this->Internal;
  const PassTexels* labels = internal.Passes[vtkLightField::LABEL].get();
  if (!labels || label < 0 || label > 255)
  {
    return false;
  }
  if (!internal.LabelsScanned)
  {
    // One pass over the label tiles through the cache (within its budget),
    // the first time a label is asked for.
    internal.Labels.fill(false);
    labels->ForEachTile(internal.Width,
      internal.Height,
      [&internal](const unsigned char* value) { internal.Labels[*value] = true; });
    internal.LabelsScanned = true;
  }
  return internal.Labels[label];
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkLightFieldImageCache::GetTilesRead()
{
  return this->Internal->Statistic("stat:tiles_created");
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkLightFieldImageCache::GetBytesRead()
{
  return this->Internal->Statistic("stat:bytes_read");
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkLightFieldImageCache::GetImageBytes()
{
  return this->Internal->Statistic("stat:image_size");
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkLightFieldImageCache::GetPeakTiles()
{
  return this->Internal->Statistic("stat:tiles_peak");
}

//------------------------------------------------------------------------------
const char* vtkLightFieldImageCache::GetError()
{
  this->Internal->Error.clear();
  for (const auto& pass : this->Internal->Passes)
  {
    if (pass && this->Internal->Error.empty())
    {
      this->Internal->Error = pass->Error();
    }
  }
  return this->Internal->Error.c_str();
}

//------------------------------------------------------------------------------
void vtkLightFieldImageCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CacheSize: " << this->CacheSize << "\n";
  os << indent << "Passes:";
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (this->HasPass(pass))
    {
      os << " " << vtkLightField::GetPassName(pass);
    }
  }
  os << "\n";
  os << indent << "TilesRead: " << this->GetTilesRead() << "\n";
  os << indent << "BytesRead: " << this->GetBytesRead() << "\n";
}
