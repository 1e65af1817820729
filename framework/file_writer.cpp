#include "file_writer.h"
#include <cerrno>
#include <cstring>
#include "errors.h"
#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

namespace ps {

namespace {
std::string reason(int err) { return err != 0 ? std::string(std::strerror(err)) : std::string("unknown reason"); }

// fsync, where the system has it. A file that cannot be synced (a pipe, a terminal, /dev/null:
// EINVAL; a file system without sync: ENOTSUP, EROFS) is not an error: its data went where it goes.
int syncFile(std::FILE* f) {
#if defined(_WIN32)
    return _commit(_fileno(f)) == 0 ? 0 : errno;
#else
    if (fsync(fileno(f)) == 0) return 0;
    const int err = errno;
    return err == EINVAL || err == ENOTSUP || err == EROFS ? 0 : err;
#endif
}
}  // namespace

FileWriter::FileWriter(const std::string& path) : path_(path) {
    errno = 0;
    f_ = std::fopen(path.c_str(), "wb");
    if (!f_) throw InputError(path_, 0, "cannot open for writing (" + reason(errno) + ")");
}

FileWriter::~FileWriter() {
    if (f_) std::fclose(f_);
}

void FileWriter::fail(const std::string& what, int err) {
    if (f_) std::fclose(f_);
    f_ = nullptr;
    throw InputError(path_, 0, what + " (" + reason(err) + ")");
}

void FileWriter::write(const void* data, size_t bytes) {
    if (!f_) throw InputError(path_, 0, "write after close");
    errno = 0;
    if (bytes > 0 && std::fwrite(data, 1, bytes, f_) != bytes) fail("write failed", errno);
}

void FileWriter::close() {
    if (!f_) throw InputError(path_, 0, "closed twice");
    errno = 0;
    if (std::fflush(f_) != 0) fail("write failed", errno);
    if (const int err = syncFile(f_)) fail("write failed: the data did not reach the device", err);
    std::FILE* f = f_;
    f_ = nullptr;
    errno = 0;
    if (std::fclose(f) != 0) throw InputError(path_, 0, "write failed when closing (" + reason(errno) + ")");
}

void writeFile(const std::string& path, const std::string& bytes) {
    FileWriter f(path);
    f.write(bytes);
    f.close();
}

int FileStream::Buffer::overflow(int c) {
    if (c == traits_type::eof()) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
}

std::streamsize FileStream::Buffer::xsputn(const char* s, std::streamsize n) {
    if (!error.empty()) return 0;
    try {
        file.write(s, size_t(n));
    } catch (const InputError& e) {
        error = e.what();
        return 0;
    }
    return n;
}

FileStream::FileStream(const std::string& path) : std::ostream(nullptr), buffer_(path) { rdbuf(&buffer_); }

void FileStream::close() {
    flush();
    if (!buffer_.error.empty()) throw InputError(buffer_.error);
    buffer_.file.close();
}

}  // namespace ps
