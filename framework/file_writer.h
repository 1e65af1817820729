// Writing a file so that a full disk or a failing device is never silent: every write, the
// flush, fsync and the close are checked, and a failure throws InputError naming the file and
// the system's reason, e.g. "out.png: write failed (No space left on device)". Every file the
// program writes goes through here (image.cpp's writers, the render command's error log, the
// converge report).
#pragma once
#include <cstdio>
#include <ostream>
#include <streambuf>
#include <string>

namespace ps {

class FileWriter {
public:
    // Opens (creates or truncates) path; InputError "cannot open for writing (reason)".
    explicit FileWriter(const std::string& path);
    // A file not closed by close() (an exception on the way) is closed without checks.
    ~FileWriter();
    FileWriter(const FileWriter&) = delete;
    FileWriter& operator=(const FileWriter&) = delete;

    // InputError "write failed (reason)".
    void write(const void* data, size_t bytes);
    void write(const std::string& text) { write(text.data(), text.size()); }
    // Flushes, asks the device to store the data (fsync; a pipe or a device that cannot sync is
    // not an error) and closes: InputError if any of them fails. Call it once, at the end.
    void close();
    const std::string& path() const { return path_; }

private:
    [[noreturn]] void fail(const std::string& what, int err);
    std::string path_;
    std::FILE* f_ = nullptr;
};

// The whole of bytes into path, checked to the end (FileWriter).
void writeFile(const std::string& path, const std::string& bytes);

// A FileWriter as a std::ostream, for text written piece by piece while the program works (the
// render loop's error log). A failed write is remembered (the stream goes bad) and close()
// throws it; close() also checks the flush, fsync and the close.
class FileStream : public std::ostream {
public:
    explicit FileStream(const std::string& path);
    void close();

private:
    struct Buffer : std::streambuf {
        explicit Buffer(const std::string& path) : file(path) {}
        int overflow(int c) override;
        std::streamsize xsputn(const char* s, std::streamsize n) override;
        FileWriter file;
        std::string error;  // the first failed write's message
    };
    Buffer buffer_;
};

}  // namespace ps
