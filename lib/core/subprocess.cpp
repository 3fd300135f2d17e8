#include "core/subprocess.hpp"

#include <cerrno>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace demscale {

CommandOutput run_command(const std::vector<std::string>& argv) {
    if (argv.empty()) throw std::invalid_argument("run_command: no program");
    int pipe_fd[2];
    if (::pipe(pipe_fd) != 0) throw std::runtime_error("cannot start " + argv[0] + ": no pipe");
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(pipe_fd[0]), ::close(pipe_fd[1]);
        throw std::runtime_error("cannot start " + argv[0] + ": fork failed");
    }
    if (pid == 0) {  // the child: both streams into the pipe, then the program
        ::dup2(pipe_fd[1], STDOUT_FILENO), ::dup2(pipe_fd[1], STDERR_FILENO);
        ::close(pipe_fd[0]), ::close(pipe_fd[1]);
        ::execvp(args[0], args.data());
        ::_exit(127);
    }
    ::close(pipe_fd[1]);
    CommandOutput out;
    char buffer[4096];
    for (ssize_t n; (n = ::read(pipe_fd[0], buffer, sizeof buffer)) != 0;) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        out.output.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(pipe_fd[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return out;
}

}  // namespace demscale
